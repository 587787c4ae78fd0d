#!/usr/bin/env bash
# The outputs a thermal analysis reads, as users run them: viewfactors and exchange correct the
# factors by default alike (--enforce both), and open rows keep their loss to space; the share to
# space per surface (viewfactors --to-space, exchange's to_space column) against the closed form
# of two facing squares and the closed cube's zero; results on the geometry as VTK files
# (exchange --vtu, solve --vtu) read back and checked against the mesh and the CSV outputs;
# solve's --samples counted per pixel; bad output paths refused before any work.
# Usage: thermal_outputs.sh RADIOSITY SOURCE_DIR WORKDIR (RADIOSITY: tests/radiosity-checked)
set -euo pipefail
radiosity=$1 source=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
squares="$source/scenes/facing-squares.gltf" cube="$source/scenes/closed-cube.gltf"
cornell="$source/scenes/cornell-box.gltf"
fail() { echo "FAIL $*"; exit 1; }
refused() {  # what file-that-must-not-appear command...
  local what=$1 left=$2
  shift 2
  local status=0
  "$@" 2>"$work/refused.log" || status=$?
  [ "$status" -eq 2 ] || { cat "$work/refused.log"; fail "$what: exit status $status"; }
  [ ! -e "$left" ] || fail "$what: $left was written"
  echo "ok   refused $what: $(head -1 "$work/refused.log")"
}

# One default correction: both, in viewfactors as in exchange.
"$radiosity" viewfactors --help | grep -q -- "--enforce TEXT:{none,reciprocity,closure,both}=both" || fail "viewfactors --enforce: default not both"
"$radiosity" exchange --help | grep -q -- "--enforce TEXT:{none,reciprocity,closure,both}=both" || fail "exchange --enforce: default not both"
"$radiosity" viewfactors "$cube" --rays 20000 --output "$work/cube.csv" --to-space "$work/cube-space.csv" \
  2>"$work/cube.log"
grep -q -- "--enforce both over 6 closed rows" "$work/cube.log" || { cat "$work/cube.log"; fail "cube: not corrected"; }
! grep -q "open rows" "$work/cube.log" || fail "the closed cube has open rows: $(cat "$work/cube.log")"
for enforce in both none; do
  "$radiosity" viewfactors "$squares" --rays 200000 --enforce $enforce --output "$work/squares-$enforce.csv" \
    --to-space "$work/space-$enforce.csv" 2>"$work/squares-$enforce.log"
done
grep -q "2 open rows lose to space up to 0.8" "$work/squares-both.log" || fail "no open rows: $(cat "$work/squares-both.log")"
python3 - "$work" <<'PY'
import csv, math, os, sys
work = sys.argv[1]
def rows(name):
    return list(csv.DictReader(open(os.path.join(work, name))))
def row_sums(table):
    sums = {}
    for r in table:
        sums[r["from"]] = sums.get(r["from"], 0.0) + float(r["F"])
    return sums
# The closed cube, corrected by default: every row sums to 1; nothing leaves.
for name, total in row_sums(rows("cube.csv")).items():
    assert abs(total - 1) < 1e-8, (name, total)
space = rows("cube-space.csv")
assert len(space) == 6, space
assert all(float(r["to_space"]) == 0 and float(r["stderr"]) == 0 for r in space), space
# Two unit squares 1 m apart: F = 0.19982 (Hottel's closed form), 1 - F to space.
x = 1.0
f = 2 / (math.pi * x * x) * (math.log(math.sqrt((1 + x * x) ** 2 / (1 + 2 * x * x))) +
                             2 * x * math.sqrt(1 + x * x) * math.atan(x / math.sqrt(1 + x * x)) - 2 * x * math.atan(x))
for enforce in ("both", "none"):
    table = rows("squares-%s.csv" % enforce)
    assert list(table[0].keys()) == ["from", "to", "F", "stderr"], table[0].keys()
    shares = {r["from"]: r for r in rows("space-%s.csv" % enforce)}
    assert list(rows("space-%s.csv" % enforce)[0].keys()) == ["from", "area", "to_space", "stderr"]
    assert set(shares) == {"bottom", "top"}, shares
    for name, total in row_sums(table).items():
        share, sigma = float(shares[name]["to_space"]), float(shares[name]["stderr"])
        assert abs(sigma - math.sqrt(f * (1 - f) / 200000)) < 1e-5, sigma  # the binomial bound
        assert abs(share - (1 - f)) <= 4 * sigma, (name, share, 1 - f, sigma)
        # Open rows are not closed by the correction: what they see of the other square stays F.
        assert abs(total - f) <= 4 * sigma, (enforce, name, total, f)
        if enforce == "none":
            assert abs(share - (1 - total)) < 2e-8, (name, share, total)  # 1 - the row's sum, exactly
    print("ok   facing squares, --enforce %s: rows sum to %s, to space %s (closed form %.6f)"
          % (enforce, sorted(round(v, 6) for v in row_sums(table).values()),
             sorted(float(r["to_space"]) for r in shares.values()), 1 - f))
# The share is that of the uncorrected factors whatever --enforce does.
assert rows("space-both.csv") == rows("space-none.csv")
PY

# exchange: to_space per surface, and the results on the patches as a VTK file.
printf 'surface,emissivity,temperature\nbottom,0.8,500\ntop,0.6,350\n' > "$work/plates.csv"
"$radiosity" exchange "$squares" --properties "$work/plates.csv" --environment-temperature 250 --rays 80000 \
  --patch-size 0.25 --output "$work/heat.csv" --vtu "$work/heat.vtu" 2>"$work/heat.log"
"$radiosity" viewfactors "$squares" --level patch --patch-size 0.25 --rays-per-patch 16 --output "$work/patch-vf.csv" \
  --patches "$work/patches.csv" 2>/dev/null
python3 - "$work" <<'PY'
import csv, math, os, re, sys
import xml.etree.ElementTree as ET
work = sys.argv[1]
x = 1.0
f = 2 / (math.pi * x * x) * (math.log(math.sqrt((1 + x * x) ** 2 / (1 + 2 * x * x))) +
                             2 * x * math.sqrt(1 + x * x) * math.atan(x / math.sqrt(1 + x * x)) - 2 * x * math.atan(x))
table = list(csv.reader(open(os.path.join(work, "heat.csv"))))
assert table[0][-4:] == ["net_heat_stderr", "temperature_stderr", "to_space", "to_space_stderr"], table[0]
assert all(len(r) == len(table[0]) for r in table)
heat = {r["surface"]: r for r in csv.DictReader(open(os.path.join(work, "heat.csv")))}
for name, r in heat.items():
    share, sigma = float(r["to_space"]), float(r["to_space_stderr"])
    binomial = math.sqrt(f * (1 - f) / 80000)
    assert 0 < sigma < binomial, (name, sigma, binomial)  # the batches' spread, below the binomial bound
    assert abs(share - (1 - f)) <= 5 * sigma, (name, share, 1 - f, sigma)
print("ok   exchange to_space: %s (closed form %.6f)" % ({n: r["to_space"] for n, r in heat.items()}, 1 - f))

text = open(os.path.join(work, "heat.vtu")).read()
names = dict((int(i), n) for i, n in re.findall(r"<!-- surface (\d+): (.*?) -->", text))
piece = ET.fromstring(text).find("UnstructuredGrid/Piece")
def array(parent, name):
    node = next(a for a in piece.find(parent) if a.get("Name") == name)
    count = int(node.get("NumberOfComponents", "1"))
    values = [float(v) for v in node.text.split()]
    return [values[k:k + count] if count > 1 else values[k] for k in range(0, len(values), count)]
points = array("Points", "Points")
cells = [array("Cells", "connectivity")[3 * k:3 * k + 3] for k in range(int(piece.get("NumberOfCells")))]
assert int(piece.get("NumberOfPoints")) == len(points)
assert array("Cells", "types") == [5.0] * len(cells)
patches = list(csv.DictReader(open(os.path.join(work, "patches.csv"))))
assert len(cells) == len(patches), (len(cells), len(patches))
surface = array("CellData", "surface")
data = {k: array("CellData", k) for k in ("area", "emissivity", "temperature", "net_flux", "net_heat", "radiosity",
                                          "irradiance", "to_space")}
sums = {}
for k, (cell, patch) in enumerate(zip(cells, patches)):
    for c in range(3):  # the patch's corners, in its order
        want = [float(patch["%s%d" % (axis, c)]) for axis in "xyz"]
        got = points[int(cell[c])]
        assert max(abs(a - b) for a, b in zip(got, want)) < 1e-6, (k, c, got, want)
    name = names[int(surface[k])]
    assert name == patch["surface"], (k, name, patch["surface"])
    r = heat[name]
    assert abs(data["area"][k] - float(patch["area"])) < 1e-6 * float(patch["area"])
    for key in ("emissivity", "temperature", "net_flux", "radiosity", "irradiance", "to_space"):
        assert abs(data[key][k] - float(r[key])) <= 1e-7 * max(1.0, abs(float(r[key]))), (key, data[key][k], r[key])
    sums[name] = sums.get(name, 0.0) + data["net_heat"][k]
for name, total in sums.items():  # the cells' parts add up to the surface's net heat
    q = float(heat[name]["net_heat"])
    assert abs(total - q) <= 1e-6 * abs(q), (name, total, q)
print("ok   exchange --vtu: %d cells on the %d patches, net heats %s" % (len(cells), len(patches), sums))
PY

# solve --vtu (into the output folder it makes): one cell per element, against elements.csv.
"$radiosity" solve "$cornell" --output "$work/solve" --rays 100000 --patch-size 0.2 --width 16 --height 12 --seed 3 \
  --quiet --element-csv --vtu "$work/solve/solution.vtu" 2>"$work/solve.log"
grep -q "solution.vtu" "$work/solve.log" || fail "solve: the summary does not name the VTU file"
python3 -c "import json, sys; o = json.load(open(sys.argv[1]))['outputs']; assert o[-1] == 'solution.vtu', o" \
  "$work/solve/report.json" || fail "solve: report.json's outputs do not list the VTU file"
# The output folder written "out/" is the same folder: no --vtu there but *.vtu, and listed by name.
status=0
"$radiosity" solve "$cornell" --output "$work/slash/" --vtu "$work/slash/render.exr" --quiet 2>"$work/slash.log" || status=$?
[ "$status" -eq 2 ] && grep -q "name it \*.vtu" "$work/slash.log" && [ ! -e "$work/slash" ] ||
  fail "solve --vtu onto render.exr in 'out/': status $status, $(cat "$work/slash.log")"
"$radiosity" solve "$cornell" --output "$work/slash/" --vtu "$work/slash/s.vtu" --rays 100000 --width 8 --height 8 \
  --quiet 2>/dev/null || fail "solve --vtu in 'out/'"
python3 -c "import json, sys; o = json.load(open(sys.argv[1]))['outputs']; assert o[-1] == 's.vtu', o" \
  "$work/slash/report.json" || fail "solve: the VTU file in 'out/' is not listed by its name"
python3 - "$work/solve" <<'PY'
import csv, os, re, sys
import xml.etree.ElementTree as ET
folder = sys.argv[1]
text = open(os.path.join(folder, "solution.vtu")).read()
names = dict((int(i), n) for i, n in re.findall(r"<!-- surface (\d+): (.*?) -->", text))
piece = ET.fromstring(text).find("UnstructuredGrid/Piece")
def array(parent, name):
    node = next(a for a in piece.find(parent) if a.get("Name") == name)
    count = int(node.get("NumberOfComponents", "1"))
    values = [float(v) for v in node.text.split()]
    return [values[k:k + count] if count > 1 else values[k] for k in range(0, len(values), count)]
points = array("Points", "Points")
connectivity = array("Cells", "connectivity")
elements = list(csv.DictReader(open(os.path.join(folder, "elements.csv"))))
assert int(piece.get("NumberOfCells")) == len(elements) > 100, (piece.get("NumberOfCells"), len(elements))
b, h = array("CellData", "radiosity"), array("CellData", "irradiance")
surface, area = array("CellData", "surface"), array("CellData", "area")
checked = 0
for k, e in enumerate(elements):
    corners = [points[int(i)] for i in connectivity[3 * k:3 * k + 3]]
    centroid = [sum(p[a] for p in corners) / 3 for a in range(3)]
    want = [float(e[a]) for a in "xyz"]
    assert max(abs(u - v) for u, v in zip(centroid, want)) < 1e-5, (k, centroid, want)
    assert names[int(surface[k])] == e["surface"], (k, names[int(surface[k])], e["surface"])
    assert abs(area[k] - float(e["area"])) <= 1e-6 * float(e["area"])
    for c, channel in enumerate("rgb"):
        assert abs(b[k][c] - float(e["B_" + channel])) <= 1e-6 * max(1.0, abs(b[k][c])), (k, b[k], e)
        rho = float(e["rho_" + channel])
        if e["surface"] != "light" and rho > 0:  # B = rho H where nothing is emitted
            assert abs(b[k][c] - rho * h[k][c]) <= 1e-5 * max(1.0, b[k][c]), (k, b[k], h[k], rho)
            checked += 1
assert checked > 100, checked
print("ok   solve --vtu: %d cells match elements.csv (positions, surfaces, radiosity); B = rho H on %d values"
      % (len(elements), checked))
PY

# --samples counts per pixel: the default is 4 (the 2 x 2 grid), any count runs, the report says it.
for samples in default 4 8 1; do
  extra=()
  [ "$samples" = default ] || extra=(--samples "$samples")
  "$radiosity" solve "$cornell" --output "$work/s-$samples" --rays 50000 --patch-size 0.3 --width 16 --height 12 \
    --seed 3 --quiet "${extra[@]}" 2>/dev/null
done
cmp "$work/s-default/render.exr" "$work/s-4/render.exr" || fail "--samples 4 is not the default image"
! cmp -s "$work/s-4/render.exr" "$work/s-8/render.exr" || fail "--samples 8 gives the same image as 4"
for samples in 4 8 1; do
  grep -q "\"samples_per_pixel\": $samples," "$work/s-$samples/report.json" || fail "report: not $samples per pixel"
done
grep -q '"samples_per_pixel": 4,' "$work/s-default/report.json" || fail "report: default not 4 per pixel"
echo "ok   --samples: default = 4 per pixel, 8 and 1 run, the report says so"

# Bad output paths, refused before any work.
refused "viewfactors --to-space into a missing folder" "$work/vf.csv" \
  "$radiosity" viewfactors "$squares" --output "$work/vf.csv" --to-space "$work/missing/space.csv"
refused "viewfactors --to-space onto --output" "$work/same.csv" \
  "$radiosity" viewfactors "$squares" --output "$work/same.csv" --to-space "$work/same.csv"
refused "exchange --vtu into a missing folder" "$work/heat2.csv" \
  "$radiosity" exchange "$squares" --properties "$work/plates.csv" --output "$work/heat2.csv" \
  --vtu "$work/missing/heat.vtu"
refused "exchange --vtu a folder" "$work/heat3.csv" \
  "$radiosity" exchange "$squares" --properties "$work/plates.csv" --output "$work/heat3.csv" --vtu "$work"
refused "solve --vtu into a missing folder" "$work/bad-solve" \
  "$radiosity" solve "$cornell" --output "$work/bad-solve" --vtu "$work/missing/s.vtu"
refused "solve --vtu onto another output" "$work/bad-solve" \
  "$radiosity" solve "$cornell" --output "$work/bad-solve" --vtu "$work/bad-solve/report.json"
refused "solve --samples 257" "$work/bad-samples" \
  "$radiosity" solve "$cornell" --output "$work/bad-samples" --samples 257
if ls "$work" | grep -q tmp; then fail "temporary file left: $(ls "$work")"; fi
