#!/usr/bin/env bash
# The same seed must give bitwise the same numbers on two OpenCL implementations (PoCL and
# Mesa's rusticl on llvmpipe): view-factor CSVs of the analytic scenes and the Cornell box, and
# the surface radiosities of solves (under an environment map, with fine elements, and overshooting
# at reflectance 0.99, a point light over a rough metal). Skips (77) when either implementation is missing.
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
# Solves NAME from SCENE with the remaining options on both implementations; their surface
# radiosities must be bitwise the same.
same_solve() {
  local name=$1 scene=$2; shift 2
  for device in pocl rusticl; do
    "$radiosity" solve "$source/$scene" --width 16 --height 16 --seed 2 --device "$device" \
      --output "$work/$name-$device" --quiet "$@" 2>/dev/null
    surfaces "$work/$name-$device/report.json" > "$work/$name-$device.surfaces"
  done
  cmp "$work/$name-pocl.surfaces" "$work/$name-rusticl.surfaces" ||
    { diff "$work/$name-pocl.surfaces" "$work/$name-rusticl.surfaces" | head; exit 1; }
  echo "solve radiosities identical: $name"
}
same_solve cornell-box scenes/cornell-box.gltf --rays 300000 --patch-size 0.08
same_solve white-furnace tests/data/solve/white-furnace.gltf --rays 300000 --patch-size 0.08
# Under an environment map, whose direct light maps directions to texels by the kernels' own arctangent.
same_solve open-box-under-a-sun tests/data/lights/open-box.gltf --environment "$source/tests/data/environment/sun.exr" \
  --rays 100000 --patch-size 0.1
# Fine elements under coarse patches (the two-level kernels).
same_solve cornell-box-elements scenes/cornell-box.gltf --rays 300000 --patch-size 0.16 --element-size 0.05
# Reflectance 0.99: overshooting's signed fixed-point sums, and rays carrying more power.
same_solve white-furnace-0.99 tests/data/solve/white-furnace-0.99.gltf --rays 300000 --patch-size 0.25
# A point light over a rough metal: the rays from the light follow its GGX lobe (light_caustics).
same_solve point-over-rough-metal tests/data/specular/point-over-rough-metal.gltf --rays 100000 --patch-size 0.25
grep -q '"ray_power_scale"' "$work/white-furnace-0.99-pocl/report.json" ||
  { echo "the 0.99 furnace did not overshoot: the check above did not test what it says"; exit 1; }
