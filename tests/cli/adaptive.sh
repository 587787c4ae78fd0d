#!/usr/bin/env bash
# Two levels and adaptive refinement from the command line: --element-size and --adaptive run,
# the report counts elements, passes and per-surface elements, --debug-mesh writes its image,
# --element-csv the solution per element,
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

"$radiosity" solve "$scene" --adaptive --rays 4e6 --width 64 --height 64 --camera plan --debug-mesh --element-csv \
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

# elements.csv: a row per element, whose areas add up to each surface's and whose area-weighted
# radiosity is the report's surface mean.
python3 - "$work/adaptive" <<'PY' || fail "elements.csv disagrees with report.json"
import csv, json, sys
d = sys.argv[1]
report = json.load(open(d + "/report.json"))
rows = list(csv.DictReader(open(d + "/elements.csv")))
assert len(rows) == report["mesh"]["elements"], (len(rows), report["mesh"]["elements"])
assert "elements.csv" in report["outputs"], report["outputs"]
for s in report["surfaces"]:
    mine = [r for r in rows if r["surface"] == s["name"]]
    area = sum(float(r["area"]) for r in mine)
    assert abs(area - s["area"]) <= 1e-4 * s["area"], (s["name"], area, s["area"])
    for c, ch in enumerate("rgb"):
        mean = sum(float(r["area"]) * float(r["B_" + ch]) for r in mine) / area
        assert abs(mean - s["radiosity"][c]) <= 1e-5 * max(1.0, abs(s["radiosity"][c])), (s["name"], ch, mean, s)
PY
echo "ok: elements.csv adds up to the report's surfaces"

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
