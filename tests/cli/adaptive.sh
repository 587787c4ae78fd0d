#!/usr/bin/env bash
# Two levels and adaptive refinement from the command line: --element-size and --adaptive run,
# the report counts elements, passes and per-surface elements, --debug-mesh writes its image,
# lit.glb holds the refined mesh, and options that cannot go together are refused with
# exit status 2 and nothing written.
# Usage: adaptive.sh RADIOSITY SOURCE_DIR WORKDIR
set -uo pipefail
radiosity=$1 source=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }
scene="$source/tests/data/solve/occluder.gltf"
field() { python3 -c "import json,sys; r=json.load(open(sys.argv[1])); print(eval(sys.argv[2]))" "$@"; }

"$radiosity" solve "$scene" --patch-size 0.25 --element-size 0.07 --rays 1e6 --width 32 --height 32 --quiet \
  --output "$work/two" 2>"$work/log" || fail "--element-size: $(cat "$work/log")"
patches=$(field "$work/two/report.json" "r['mesh']['patches']")
elements=$(field "$work/two/report.json" "r['mesh']['elements']")
[ "$elements" -ge $((16 * patches)) ] || fail "--element-size 0.07 under 0.25 m patches gave $elements elements for $patches patches"
echo "ok: two levels, $patches patches, $elements elements"

"$radiosity" solve "$scene" --adaptive --rays 4e6 --width 64 --height 64 --camera plan --debug-mesh \
  --output "$work/adaptive" 2>"$work/log" || fail "--adaptive: $(cat "$work/log")"
grep -q "refinement pass 1 (direct light)" "$work/log" || fail "no refinement pass reported: $(cat "$work/log")"
[ "$(field "$work/adaptive/report.json" "r['mesh']['adaptive']")" = True ] || fail "report: adaptive"
[ "$(field "$work/adaptive/report.json" "r['mesh']['refinement_passes'] >= 1")" = True ] || fail "report: passes"
[ "$(field "$work/adaptive/report.json" "r['mesh']['elements'] > r['mesh']['patches']")" = True ] || fail "nothing refined"
[ "$(field "$work/adaptive/report.json" "sum(s['elements'] for s in r['surfaces']) == r['mesh']['elements']")" = True ] ||
  fail "per-surface elements do not add up"
[ -s "$work/adaptive/render-mesh.png" ] || fail "--debug-mesh wrote no render-mesh.png"
[ -s "$work/adaptive/lit.glb" ] || fail "no lit.glb"
echo "ok: adaptive, $(field "$work/adaptive/report.json" "r['mesh']['elements']") elements"

refuse() {  # expected failure with exit status 2, a message naming the option, no output
  local name=$1 needle=$2; shift 2
  "$radiosity" solve "$scene" "$@" --quiet --output "$work/$name" 2>"$work/log"
  local status=$?
  [ $status -eq 2 ] || fail "$name exited $status: $(cat "$work/log")"
  grep -q -- "$needle" "$work/log" || fail "$name: $(cat "$work/log")"
  [ ! -e "$work/$name" ] || fail "$name left output"
  echo "ok: refused $name: $(cat "$work/log")"
}
refuse adaptive-matrix "--adaptive" --adaptive --solver jacobi
refuse adaptive-resume "--adaptive" --adaptive --resume "$work/none.ckpt"
refuse elements-hemicube "--element-size" --element-size 0.05 --method hemicube
