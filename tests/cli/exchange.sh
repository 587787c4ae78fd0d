#!/usr/bin/env bash
# radiosity exchange as users run it (and viewfactors --target-error): concentric spheres
# against the closed form, a reradiating enclosure at the inner sphere's temperature, the
# exchange-factor file, bad properties refused naming the file and the line with no output left
# behind, and view factors to a target error.
# Usage: exchange.sh RADIOSITY SOURCE_DIR WORKDIR
set -euo pipefail
radiosity=$1 source=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
scene="$source/tests/data/thermal/concentric-spheres.gltf"

"$radiosity" exchange "$scene" --properties "$source/tests/data/thermal/spheres.csv" --rays 80000 \
  --output "$work/heat.csv" --exchange "$work/gebhart.csv" 2>"$work/stderr"
python3 - "$work/heat.csv" "$work/gebhart.csv" <<'PY'
import csv, sys
table = list(csv.reader(open(sys.argv[1])))
assert all(len(r) == len(table[0]) for r in table), "rows and header differ in length"
assert table[0][-4:] == ["net_heat_stderr", "temperature_stderr", "to_space", "to_space_stderr"], table[0]
rows = {r["surface"]: r for r in csv.DictReader(open(sys.argv[1]))}
a1, a2 = float(rows["inner"]["area"]), float(rows["outer"]["area"])
sigma = 5.670374419e-8
q = sigma * a1 * (400.0**4 - 300.0**4) / (1 / 0.8 + (a1 / a2) * (1 / 0.5 - 1))
got = float(rows["inner"]["net_heat"])
assert abs(got - q) <= 1e-6 * q, (got, q)
assert abs(float(rows["outer"]["net_heat"]) + q) <= 1e-6 * q
assert all(float(r["to_space"]) == 0 for r in rows.values()), rows  # closed: nothing leaves
g = {(r["from"], r["to"]): float(r["exchange_factor"]) for r in csv.DictReader(open(sys.argv[2]))}
for s in ("inner", "outer"):  # closed: every row of exchange factors sums to 1
    total = sum(v for (f, t), v in g.items() if f == s)
    assert abs(total - 1) < 1e-9, (s, total)
print("ok   spheres: net heat %.6f W, closed form %.6f W; exchange factors close" % (got, q))
PY
grep -q "net heats sum to" "$work/stderr" || { echo "FAIL: no energy summary"; cat "$work/stderr"; exit 1; }

"$radiosity" exchange "$scene" --properties "$source/tests/data/thermal/spheres-reradiating.csv" --rays 8000 \
  --output "$work/reradiating.csv" 2>/dev/null
python3 - "$work/reradiating.csv" <<'PY'
import csv, sys
rows = {r["surface"]: r for r in csv.DictReader(open(sys.argv[1]))}
t = float(rows["outer"]["temperature"])
assert abs(t - 400.0) < 1e-6, t  # a reradiating enclosure takes the temperature of what it holds
print("ok   reradiating: outer sphere at %.6f K" % t)
PY

fail() { echo "FAIL $*"; exit 1; }
expect_refusal() {  # what csv-text
  printf '%b' "$2" > "$work/bad.csv"
  rm -f "$work/out.csv"
  set +e
  "$radiosity" exchange "$scene" --properties "$work/bad.csv" --rays 800 --output "$work/out.csv" 2>"$work/stderr"
  local status=$?
  set -e
  [ "$status" -eq 2 ] || fail "$1: exit status $status"
  grep -q "bad.csv: $3" "$work/stderr" || { cat "$work/stderr"; fail "$1: message does not say '$3'"; }
  [ ! -e "$work/out.csv" ] || fail "$1: left an output behind"
  echo "ok   $1: $(cat "$work/stderr")"
}
expect_refusal "unknown surface" "surface,emissivity,temperature\ninner,0.5,300\nmiddle,0.5,300\n" "line 3: the scene has no surface side named 'middle'"
expect_refusal "emissivity above 1" "surface,emissivity,temperature\ninner,1.2,300\nouter,0.5,300\n" "line 2: the emissivity of 'inner' is 1.2"
expect_refusal "negative temperature" "surface,emissivity,temperature\ninner,0.5,-3\nouter,0.5,300\n" "line 2: the temperature of 'inner' is negative"
expect_refusal "missing column" "surface,temperature\ninner,300\n" "line 1: the header has no 'emissivity' column"
set +e
"$radiosity" exchange "$scene" --properties "$source/tests/data/thermal/missing.csv" --output "$work/out.csv" 2>"$work/stderr"
status=$?
set -e
[ "$status" -eq 2 ] && grep -q "missing.csv: cannot open" "$work/stderr" || fail "missing properties file"
echo "ok   missing file: $(cat "$work/stderr")"

# viewfactors --target-error: every stderr within the target, and the rays it took reported.
"$radiosity" viewfactors "$source/scenes/closed-cube.gltf" --target-error 2e-3 --output "$work/vf.csv" 2>"$work/stderr"
python3 - "$work/vf.csv" <<'PY'
import csv, sys
worst = max(float(r["stderr"]) for r in csv.DictReader(open(sys.argv[1])))
assert worst <= 2e-3, worst
print("ok   viewfactors --target-error 2e-3: largest stderr %g" % worst)
PY
grep -q "rays per surface in [0-9]* rounds" "$work/stderr" || fail "no rays and rounds reported: $(cat "$work/stderr")"

# The exchange factors as Matrix Market: a header, one comment per surface, every row summing to 1.
"$radiosity" exchange "$scene" --properties "$source/tests/data/thermal/spheres.csv" --rays 8000 \
  --output "$work/heat.csv" --exchange "$work/gebhart.mtx" --exchange-format mtx 2>/dev/null
python3 - "$work/gebhart.mtx" <<'PY'
import sys
lines = open(sys.argv[1]).read().splitlines()
assert lines[0] == "%%MatrixMarket matrix coordinate real general", lines[0]
assert sum(1 for l in lines if l.startswith("% ") and " emissivity " in l) == 2
body = [l for l in lines if not l.startswith("%")]
rows, cols, nonzeros = map(int, body[0].split())
assert (rows, cols, nonzeros) == (2, 2, len(body) - 1)
sums = {}
for l in body[1:]:
    i, j, v = l.split()
    sums[i] = sums.get(i, 0.0) + float(v)
assert all(abs(s - 1) < 1e-8 for s in sums.values()), sums
print("ok   exchange factors as Matrix Market: rows sum to 1")
PY
