#!/usr/bin/env bash
# Every broken scene: exit status 2, one line on stderr naming the file, no output file left.
# Usage: bad_input.sh RADIOSITY DATA_DIR WORKDIR
set -uo pipefail
radiosity=$1 data=$2 work=$3
mkdir -p "$work"
failures=0
check() {  # expected-status description command...
  local expected=$1 what=$2
  shift 2
  rm -f "$work"/out.csv* "$work/stderr"
  "$@" >/dev/null 2>"$work/stderr"
  local status=$?
  local lines
  lines=$(wc -l < "$work/stderr")
  if [ "$status" -ne "$expected" ]; then
    echo "FAIL $what: exit status $status, expected $expected"; cat "$work/stderr"; failures=$((failures + 1))
  elif [ "$expected" -ne 0 ] && [ "$lines" -ne 1 ]; then
    echo "FAIL $what: $lines lines on stderr, expected 1"; cat "$work/stderr"; failures=$((failures + 1))
  elif compgen -G "$work/out.csv*" >/dev/null; then
    echo "FAIL $what: left an output file behind"; failures=$((failures + 1))
  else
    echo "ok   $what: $(head -c 160 "$work/stderr")"
  fi
}
for file in "$data"/*.gltf "$data"/*.glb; do
  check 2 "$(basename "$file")" "$radiosity" viewfactors "$file" --rays 1000 --output "$work/out.csv"
  grep -q "$(basename "$file")" "$work/stderr" || { echo "FAIL $(basename "$file"): message does not name the file"; failures=$((failures + 1)); }
done
for file in "$data"/*.obj "$data"/*.stl "$data"/*.ply; do  # the mesh formats (scenes/mesh_scenes.py)
  check 2 "$(basename "$file")" "$radiosity" viewfactors "$file" --rays 1000 --output "$work/out.csv"
  grep -q "$(basename "$file")" "$work/stderr" || { echo "FAIL $(basename "$file"): message does not name the file"; failures=$((failures + 1)); }
done
check 2 "missing file" "$radiosity" viewfactors "$work/nothing-here.gltf" --output "$work/out.csv"
check 2 "a missing STL beside a good one" "$radiosity" viewfactors "$data/../meshes/floor.stl" "$work/nothing.stl" --output "$work/out.csv"
check 2 "a glTF file beside an STL" "$radiosity" viewfactors "$data/../gltf/fan.gltf" "$data/../meshes/floor.stl" --output "$work/out.csv"
check 2 "--unit mm with glTF" "$radiosity" viewfactors "$data/../gltf/fan.gltf" --unit mm --output "$work/out.csv"
check 2 "--patches without --level patch" "$radiosity" viewfactors "$data/../meshes/floor.stl" --patches "$work/out.csv.patches" --output "$work/out.csv"
check 2 "--patches into a missing folder" "$radiosity" viewfactors "$data/../meshes/floor.stl" --level patch --patches "$work/no-such-folder/p.csv" --output "$work/out.csv"
check 2 "--patches and --output the same file" "$radiosity" viewfactors "$data/../meshes/floor.stl" --level patch --patches "$work/out.csv" --output "$work/out.csv"
check 2 "--unit furlong" "$radiosity" viewfactors "$data/../meshes/floor.stl" --unit furlong --output "$work/out.csv"
check 2 "zero rays" "$radiosity" viewfactors "$data/../gltf/fan.gltf" --rays 0 --output "$work/out.csv"
check 2 "negative patch size" "$radiosity" viewfactors "$data/../gltf/fan.gltf" --patch-size -1 --output "$work/out.csv"
check 2 "unknown option" "$radiosity" viewfactors "$data/../gltf/fan.gltf" --no-such-option
check 2 "unknown device" "$radiosity" viewfactors "$data/../gltf/fan.gltf" --device no-such-device --output "$work/out.csv"
check 2 "no subcommand" "$radiosity"
# Each command's declared checks (app/cli_options.h): out of range, not a choice, a missing flag.
check 2 "solve: width 0" "$radiosity" solve "$data/../gltf/fan.gltf" --width 0 --output "$work/out.csv"
check 2 "solve: an unknown camera pass" "$radiosity" solve "$data/../gltf/fan.gltf" --render nope --output "$work/out.csv"
check 2 "solve: a lightmap option without --lightmap" "$radiosity" solve "$data/../gltf/fan.gltf" --lightmap-samples 4 --output "$work/out.csv"
check 2 "pathtrace: 0.5 samples" "$radiosity" pathtrace "$data/../gltf/fan.gltf" --samples 0.5 --output "$work/out.csv"
check 2 "pathtrace: a noise target of 2" "$radiosity" pathtrace "$data/../gltf/fan.gltf" --noise 2 --output "$work/out.csv"
check 2 "solve: 300 samples in the radiosity mode" "$radiosity" solve "$data/../gltf/fan.gltf" --samples 300 --output "$work/out.csv"
check 2 "solve: a noise target in the radiosity mode" "$radiosity" solve "$data/../gltf/fan.gltf" --noise 0.01 --output "$work/out.csv"
check 2 "exchange: one batch" "$radiosity" exchange "$data/../gltf/fan.gltf" --properties x.csv --batches 1 --output "$work/out.csv"
check 2 "viewfactors: a level that is not one" "$radiosity" viewfactors "$data/../gltf/fan.gltf" --level element --output "$work/out.csv"
check 0 "help" "$radiosity" --help
# solve: refusals that happen before any work, with no output directory left behind.
check 2 "solve: nothing emits" "$radiosity" solve "$data/../gltf/fan.gltf" --output "$work/out.csv"
for way in "emissive factor" "KHR_lights_punctual" "--sky" "--environment"; do  # every way light can enter is named
  grep -q -- "$way" "$work/stderr" || { echo "FAIL solve: nothing emits: message does not name $way"; failures=$((failures + 1)); }
done
check 2 "solve: a bad sky" "$radiosity" solve "$data/../gltf/fan.gltf" --sky 1,2 --output "$work/out.csv"
check 2 "solve: a negative sky" "$radiosity" solve "$data/../gltf/fan.gltf" --sky -1 --output "$work/out.csv"
# Environment maps that cannot light anything: refused naming the map, for solve and pathtrace.
for map in "$data"/../environment/bad-*.exr "$data/../environment/no-such-map.exr"; do
  for command in solve pathtrace; do
    check 2 "$command: $(basename "$map")" "$radiosity" "$command" "$data/../environment/plane.gltf" \
      --environment "$map" --output "$work/out.csv"
    grep -q "$(basename "$map")" "$work/stderr" || { echo "FAIL $(basename "$map"): message does not name the map"; failures=$((failures + 1)); }
  done
done
check 2 "solve: a sky and a map" "$radiosity" solve "$data/../environment/plane.gltf" --sky 1 \
  --environment "$data/../environment/uniform.exr" --output "$work/out.csv"
check 2 "solve: a zero map strength" "$radiosity" solve "$data/../environment/plane.gltf" \
  --environment "$data/../environment/uniform.exr" --environment-strength 0 --output "$work/out.csv"
check 2 "solve: unknown camera" "$radiosity" solve "$data/../../../scenes/cornell-box.gltf" --camera nope --output "$work/out.csv"
check 2 "solve: tolerance 0 without a limit" "$radiosity" solve "$data/../../../scenes/cornell-box.gltf" --tolerance 0 --output "$work/out.csv"
check 2 "solve: broken scene" "$radiosity" solve "$data/node-cycle.gltf" --output "$work/out.csv"
touch "$work/a-file"
check 2 "solve: output is a file" "$radiosity" solve "$data/../../../scenes/cornell-box.gltf" --output "$work/a-file"
exit $((failures > 0))
