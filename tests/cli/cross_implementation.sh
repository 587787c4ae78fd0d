#!/usr/bin/env bash
# The same seed must give bitwise the same numbers on two OpenCL implementations (PoCL and
# Mesa's rusticl on llvmpipe): view-factor CSVs of the analytic scenes and the Cornell box, and
# the surface radiosities of solves (one lit by an environment map, whose direct light maps
# directions to texels by the kernels' own arctangent). Skips (77) when either implementation is missing.
# Usage: cross_implementation.sh RADIOSITY SOURCE_DIR WORKDIR
set -euo pipefail
radiosity=$1 source=$2 work=$3
export RUSTICL_ENABLE=llvmpipe
for device in pocl rusticl; do
  "$radiosity" devices 2>/dev/null | grep -qi "$device" || { echo "no $device device: skipped"; exit 77; }
done
rm -rf "$work" && mkdir -p "$work"
surfaces() { awk '/^  "surfaces": \[/{on=1} on{print} on&&/^  \],?$/{exit}' "$1"; }
for scene in facing-squares perpendicular-squares coaxial-disks closed-cube cornell-box; do
  for device in pocl rusticl; do
    "$radiosity" viewfactors "$source/scenes/$scene.gltf" --rays 100000 --seed 11 --device "$device" \
      --output "$work/$scene-$device.csv" 2>/dev/null
  done
  cmp "$work/$scene-pocl.csv" "$work/$scene-rusticl.csv" || { diff "$work/$scene-pocl.csv" "$work/$scene-rusticl.csv" | head; exit 1; }
  echo "view factors identical: $scene"
done
for scene in scenes/cornell-box.gltf tests/data/solve/white-furnace.gltf; do
  name=$(basename "$scene" .gltf)
  for device in pocl rusticl; do
    "$radiosity" solve "$source/$scene" --rays 300000 --patch-size 0.08 --width 32 --height 32 --seed 2 \
      --device "$device" --output "$work/$name-$device" --quiet 2>/dev/null
    surfaces "$work/$name-$device/report.json" > "$work/$name-$device.surfaces"
  done
  cmp "$work/$name-pocl.surfaces" "$work/$name-rusticl.surfaces" || { diff "$work/$name-pocl.surfaces" "$work/$name-rusticl.surfaces" | head; exit 1; }
  echo "solve radiosities identical: $name"
done
for device in pocl rusticl; do
  "$radiosity" solve "$source/tests/data/lights/open-box.gltf" --environment "$source/tests/data/environment/sun.exr" \
    --rays 100000 --patch-size 0.1 --width 16 --height 16 --seed 2 --device "$device" --output "$work/env-$device" \
    --quiet 2>/dev/null
  surfaces "$work/env-$device/report.json" > "$work/env-$device.surfaces"
done
cmp "$work/env-pocl.surfaces" "$work/env-rusticl.surfaces" || { diff "$work/env-pocl.surfaces" "$work/env-rusticl.surfaces" | head; exit 1; }
echo "solve radiosities identical: open box under an environment map"
