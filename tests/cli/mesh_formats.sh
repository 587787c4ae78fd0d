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
# Saved by a Windows editor: a UTF-8 byte-order mark first, CRLF line ends. The same bytes.
mkdir -p "$work/windows"
{ printf '\xef\xbb\xbf'; grep -v '^#' room.mtl; } | sed 's/$/\r/' > "$work/windows/room.mtl"  # newmtl first
# (its first vertex first, where a mark left in place would hide the line's keyword)
{ printf '\xef\xbb\xbf'; grep -m1 '^v ' room.obj; grep -v '^#' room.obj | awk '/^v / && !seen { seen = 1; next } 1'; } |
  sed 's/$/\r/' > "$work/windows/room.obj"
"$radiosity" viewfactors "$work/windows/room.obj" --rays 20000 --output "$work/windows.csv" 2>/dev/null
cmp "$work/gltf.csv" "$work/windows.csv" || { echo "FAIL: an OBJ with a byte-order mark and CRLF reads otherwise"; exit 1; }
echo "ok   an OBJ with a UTF-8 byte-order mark and CRLF line ends: the same bytes"
# The floor sees the back of the tilted panel: viewfactors says how much of its row is lost there.
"$radiosity" viewfactors room-plain.gltf --rays 20000 --output "$work/backs.csv" 2>"$work/backs.txt"
grep -q "of the rays from 'floor' stop on the back of a single-sided face" "$work/backs.txt" ||
  { echo "FAIL: no warning of rays lost on backs"; cat "$work/backs.txt"; exit 1; }
if grep -q "rays from '\(panel\|lamp\)' stop on the back" "$work/backs.txt"; then
  echo "FAIL: a warning for a surface that sees no back"; cat "$work/backs.txt"; exit 1
fi
echo "ok   rays lost on backs: $(grep -o "[0-9.]* % of the rays from 'floor'" "$work/backs.txt")"
# The same at --level patch, from the patch matrix's rays: per surface, its patches' shares.
"$radiosity" viewfactors room-plain.gltf --level patch --rays-per-patch 2048 --output "$work/patch-backs.csv" \
  2>"$work/patch-backs.txt"
python3 - "$work/backs.txt" "$work/patch-backs.txt" <<'PY'
import re, sys
def share(path):
    found = re.findall(r"([0-9.]+) % of the rays from '(\w+)' stop on the back", open(path).read())
    assert [name for _, name in found] == ["floor"], (path, found)
    return float(found[0][0]) / 100
surface, patches = share(sys.argv[1]), share(sys.argv[2])
# Both binomial estimates of one share: 20,000 rays, and 2048 per patch over the floor's patches
# (at least 2048 in all); within five standard errors of their difference.
sigma = (surface * (1 - surface) * (1 / 20000 + 1 / 2048)) ** 0.5
assert abs(surface - patches) <= 5 * sigma, (surface, patches, sigma)
print("ok   --level patch: the floor's rays lost on backs, %.3g against %.3g from surface rows" % (patches, surface))
PY

"$radiosity" solve room.gltf --output "$work/solve-gltf" --render direct --width 16 --height 16 --quiet 2>/dev/null
"$radiosity" solve room.obj --output "$work/solve-obj" --render direct --width 16 --height 16 --quiet 2>/dev/null
"$radiosity" solve "$work/windows/room.obj" --output "$work/solve-windows" --render direct --width 16 --height 16 \
  --quiet 2>/dev/null
python3 - "$work/solve-gltf/report.json" "$work/solve-obj/report.json" "$work/solve-windows/report.json" <<'PY'
import json, sys
a, b, c = (json.load(open(p)) for p in sys.argv[1:4])
assert a["surfaces"] == b["surfaces"], (a["surfaces"], b["surfaces"])
assert a["solve"]["shots"] == b["solve"]["shots"], (a["solve"], b["solve"])
assert b["scene"].endswith("room.obj"), b["scene"]
assert c["surfaces"] == b["surfaces"], ("byte-order marks and CRLF", c["surfaces"], b["surfaces"])
print("ok   solve: the OBJ's surfaces and shots are the glTF file's, bit for bit (%d surfaces), and so are "
      "those of the OBJ and MTL with byte-order marks and CRLF" % len(a["surfaces"]))
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

# --patches: where each patch of --level patch is, in the file's coordinates.
"$radiosity" viewfactors room-plain.gltf --level patch --patch-size 0.5 --rays-per-patch 256 \
  --output "$work/patch-vf.csv" --patches "$work/patches.csv" 2>/dev/null
python3 - "$work/patch-vf.csv" "$work/patches.csv" <<'PY'
import csv, math, sys
factors = list(csv.DictReader(open(sys.argv[1])))
patches = {r["patch"]: r for r in csv.DictReader(open(sys.argv[2]))}
assert {r["from"] for r in factors} | {r["to"] for r in factors} <= patches.keys()
area = {}
for name, r in patches.items():
    corners = [[float(r["%s%d" % (axis, k)]) for axis in "xyz"] for k in range(3)]
    centroid = [float(r["centroid_" + axis]) for axis in "xyz"]
    normal = [float(r["normal_" + axis]) for axis in "xyz"]
    edge1 = [corners[1][i] - corners[0][i] for i in range(3)]
    edge2 = [corners[2][i] - corners[0][i] for i in range(3)]
    cross = [edge1[1] * edge2[2] - edge1[2] * edge2[1], edge1[2] * edge2[0] - edge1[0] * edge2[2],
             edge1[0] * edge2[1] - edge1[1] * edge2[0]]
    twice = math.sqrt(sum(c * c for c in cross))
    assert abs(0.5 * twice - float(r["area"])) <= 1e-5 * float(r["area"]), (name, twice, r["area"])
    assert all(abs(cross[i] / twice - normal[i]) < 1e-5 for i in range(3)), (name, cross, normal)  # counter-clockwise
    assert all(abs(sum(c[i] for c in corners) / 3 - centroid[i]) < 1e-6 for i in range(3)), name
    area[r["surface"]] = area.get(r["surface"], 0.0) + float(r["area"])
# In the file's coordinates: the floor lies at y = 0.021 and the lamp at 1.221 (scenes/mesh_scenes.py).
ys = [float(r["y%d" % k]) for r in patches.values() for k in range(3)]
assert abs(min(ys) - 0.021) < 1e-6 and abs(max(ys) - 1.221) < 1e-6, (min(ys), max(ys))
for surface, expected in (("floor", 1.1 * 1.3), ("lamp", 0.5 * 0.5)):
    assert abs(area[surface] - expected) < 1e-5 * expected, (surface, area[surface], expected)
print("ok   --patches: %d patches, corners, normals and centroids agree; floor %.6f m^2, lamp %.6f m^2"
      % (len(patches), area["floor"], area["lamp"]))
PY
