#!/usr/bin/env bash
# OBJ, STL and PLY as users give them: the room of tests/data/meshes/ as glTF, as one OBJ with
# its MTL, as three STL files and as three PLY files gives byte-identical view factors; solve on
# the OBJ gives the glTF file's surface radiosities bit for bit (the MTL's Kd and Ke are the glTF
# materials'); --unit mm gives the same view factors at a thousandth of the area.
# Usage: mesh_formats.sh RADIOSITY SOURCE_DIR WORKDIR
set -euo pipefail
radiosity=$(realpath "$1") data=$2/tests/data/meshes work=$3
rm -rf "$work" && mkdir -p "$work"
cd "$data"
"$radiosity" viewfactors room-plain.gltf --rays 20000 --output "$work/gltf.csv" 2>/dev/null
"$radiosity" viewfactors room.obj --rays 20000 --output "$work/obj.csv" 2>/dev/null
"$radiosity" viewfactors floor.stl panel.stl lamp.stl --rays 20000 --output "$work/stl.csv" 2>/dev/null
"$radiosity" viewfactors floor.ply panel.ply lamp.ply --rays 20000 --output "$work/ply.csv" 2>/dev/null
"$radiosity" viewfactors floor.ply panel.stl lamp.ply --rays 20000 --output "$work/mixed.csv" 2>/dev/null
for format in obj stl ply mixed; do
  cmp "$work/gltf.csv" "$work/$format.csv" || { echo "FAIL: $format view factors differ from glTF's"; exit 1; }
done
echo "ok   view factors: glTF, OBJ, STL, PLY and a mix give the same bytes ($(($(wc -l < "$work/gltf.csv") - 1)) rows)"

"$radiosity" solve room.gltf --output "$work/solve-gltf" --render direct --width 16 --height 16 --quiet 2>/dev/null
"$radiosity" solve room.obj --output "$work/solve-obj" --render direct --width 16 --height 16 --quiet 2>/dev/null
python3 - "$work/solve-gltf/report.json" "$work/solve-obj/report.json" <<'PY'
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:3])
assert a["surfaces"] == b["surfaces"], (a["surfaces"], b["surfaces"])
assert a["solve"]["shots"] == b["solve"]["shots"], (a["solve"], b["solve"])
assert b["scene"].endswith("room.obj"), b["scene"]
print("ok   solve: the OBJ's surfaces and shots are the glTF file's, bit for bit (%d surfaces)" % len(a["surfaces"]))
PY

"$radiosity" exchange floor.stl panel.stl lamp.stl --properties room-properties.csv --rays 2000 \
  --output "$work/metres.csv" 2>/dev/null
"$radiosity" exchange floor.stl panel.stl lamp.stl --unit mm --properties room-properties.csv --rays 2000 \
  --output "$work/millimetres.csv" 2>/dev/null
python3 - "$work/metres.csv" "$work/millimetres.csv" <<'PY'
import csv, sys
m, mm = ({r["surface"]: float(r["area"]) for r in csv.DictReader(open(p))} for p in sys.argv[1:3])
assert m.keys() == mm.keys() == {"floor", "panel", "lamp"}, (m, mm)
for name in m:
    assert abs(mm[name] - 1e-6 * m[name]) <= 1e-6 * 1e-6 * m[name], (name, m[name], mm[name])
print("ok   --unit mm: areas a millionth of the metres' (%s)" % ", ".join("%s %.4g m^2" % kv for kv in mm.items()))
PY
