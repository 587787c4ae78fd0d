#!/usr/bin/env bash
# solve --properties: materials from the CSV file exchange reads, for mesh files (which carry
# none) and glTF alike.
# 1. The facing squares (unit squares one apart, F = 0.199825), the bottom made an emitter of
#    radiance 1 that reflects nothing and the top a white reflector: the top's mean radiosity is
#    pi F (every ray from the bottom that reaches the top is reflected once; what the top sends
#    back is absorbed), within five binomial standard errors of the rays the solve cast.
# 2. The STL room (tests/data/meshes/) lit only by the file's lamp emission: the lamp's mean
#    radiosity is at least pi x its radiance, and exchange reads the same file, giving the same
#    bytes as with the thermal columns alone.
# 3. Bad files are refused naming the file, the line and the problem, with nothing written.
# Usage: properties.sh RADIOSITY SOURCE_DIR WORKDIR
set -euo pipefail
radiosity=$1 source=$2 work=$3
rm -rf "$work" && mkdir -p "$work"

printf 'surface,reflectance,emission\nbottom,0,1\ntop,1,0\n' > "$work/squares.csv"
"$radiosity" solve "$source/scenes/facing-squares.gltf" --properties "$work/squares.csv" --output "$work/squares" \
  --width 8 --height 8 --quiet 2>/dev/null
python3 - "$work/squares/report.json" <<'PY'
import json, math, sys
r = json.load(open(sys.argv[1]))
B = {s["name"]: s["radiosity"][0] for s in r["surfaces"]}
F, rays = 0.199825, r["solve"]["rays"]
expected = math.pi * F
sigma = math.pi * math.sqrt(F * (1 - F) / rays)
assert abs(B["bottom"] - math.pi) < 1e-5, B
assert abs(B["top"] - expected) <= 5 * sigma, (B, expected, sigma)
print("ok   facing squares: top %.6f against pi F = %.6f (5 sigma %.2g over %d rays), bottom %.6f = pi" %
      (B["top"], expected, 5 * sigma, rays, B["bottom"]))
PY

meshes="$source/tests/data/meshes"
printf 'surface,emissivity,temperature,reflectance,emission_r,emission_g,emission_b\nfloor,0.9,300,0.5,,,\npanel,0.8,350,0.7,,,\nlamp,0.9,500,0.2,10,8,6\n' > "$work/room.csv"
"$radiosity" solve "$meshes/floor.stl" "$meshes/panel.stl" "$meshes/lamp.stl" --properties "$work/room.csv" \
  --output "$work/room" --width 8 --height 8 --rays 1e6 --quiet 2>/dev/null
python3 - "$work/room/report.json" <<'PY'
import json, math, sys
B = {s["name"]: s["radiosity"] for s in json.load(open(sys.argv[1]))["surfaces"]}
for c, L in enumerate((10, 8, 6)):
    assert B["lamp"][c] >= math.pi * L, B
assert B["floor"][0] > 0 and B["panel"][0] > 0, B
print("ok   STL room lit by --properties: lamp %s, floor %.4f, panel %.4f" %
      (["%.3f" % b for b in B["lamp"]], B["floor"][0], B["panel"][0]))
PY
"$radiosity" exchange "$meshes/floor.stl" "$meshes/panel.stl" "$meshes/lamp.stl" --properties "$work/room.csv" \
  --rays 20000 --output "$work/with-materials.csv" 2>/dev/null
"$radiosity" exchange "$meshes/floor.stl" "$meshes/panel.stl" "$meshes/lamp.stl" \
  --properties "$meshes/room-properties.csv" --rays 20000 --output "$work/thermal-only.csv" 2>/dev/null
cmp "$work/with-materials.csv" "$work/thermal-only.csv"
echo "ok   exchange reads the same file, ignoring the material columns"

bad() {  # name, file contents, words the message must hold
  printf "$2" > "$work/$1.csv"
  status=0
  "$radiosity" solve "$source/scenes/facing-squares.gltf" --properties "$work/$1.csv" --output "$work/out-$1" \
    2>"$work/stderr" || status=$?
  [ "$status" -eq 2 ] || { echo "FAIL $1: exit status $status, expected 2"; cat "$work/stderr"; exit 1; }
  grep -qF "$1.csv" "$work/stderr" && grep -qF "$3" "$work/stderr" ||
    { echo "FAIL $1: the message does not name the file and '$3'"; cat "$work/stderr"; exit 1; }
  [ ! -e "$work/out-$1" ] || { echo "FAIL $1: wrote output"; exit 1; }
  echo "ok   $1: $(cat "$work/stderr")"
}
bad unknown-surface 'surface,reflectance\nroof,0.5\n' "line 2: the scene has no surface named 'roof'"
bad reflectance-range 'surface,reflectance\ntop,1.5\n' "line 2: the reflectance of 'top' lies outside [0, 1]"
bad negative-emission 'surface,emission\ntop,-1\n' "the emission of 'top' is negative"
bad twice 'surface,reflectance\ntop,0.5\ntop,0.4\n' "line 3: surface 'top' is listed twice"
bad unknown-column 'surface,albedo\ntop,0.5\n' "line 1: unknown column 'albedo'"
bad partial-channels 'surface,reflectance_r,reflectance_g\ntop,0.5,0.5\n' "needs all three columns"
bad grey-and-channels 'surface,reflectance,reflectance_r,reflectance_g,reflectance_b\ntop,1,1,1,1\n' "give one or the other"
bad not-a-number 'surface,reflectance\ntop,bright\n' "reflectance 'bright' is not a finite number"
bad no-columns 'surface,emissivity\ntop,0.5\n' "no reflectance or emission column"
