#!/usr/bin/env bash
# Writes the outputs the cross-device comparison uses into DIR: view-factor CSVs of the bundled
# scenes and the surface radiosities of two solves, all with fixed seeds. Run it on each
# device (--device D) and compare the folders with `diff -r`.
# Usage: bench/gpu-compare.sh RADIOSITY DEVICE DIR
set -euo pipefail
radiosity=$1 device=$2 dir=$3
mkdir -p "$dir"
for scene in facing-squares perpendicular-squares coaxial-disks closed-cube cornell-box; do
  "$radiosity" viewfactors "scenes/$scene.gltf" --seed 11 --device "$device" --output "$dir/$scene.csv" 2>/dev/null
done
for scene in scenes/cornell-box.gltf tests/data/solve/white-furnace.gltf; do
  name=$(basename "$scene" .gltf)
  "$radiosity" solve "$scene" --seed 2 --device "$device" --output "$dir/solve-$name" --quiet 2>"$dir/solve-$name.log"
  awk '/^  "surfaces": \[/{on=1} on{print} on&&/^  \],?$/{exit}' "$dir/solve-$name/report.json" > "$dir/$name.surfaces"
  rm -rf "$dir/solve-$name"
done
