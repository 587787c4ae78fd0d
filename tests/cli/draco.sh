#!/usr/bin/env bash
# KHR_draco_mesh_compression as users meet it: two quads written by libdraco's own encoder
# (tests/tools/draco_fixtures.cpp). Without quantization the compressed file gives the plain
# file's view factors byte for byte; with 11-bit positions they agree within four standard
# errors; an attribute id the compressed mesh lacks and compressed bytes cut short are
# refused with exit status 2, naming the file and the problem, and nothing written; vertex
# colours (COLOR_0) compressed give the plain file's image.
# Usage: draco.sh RADIOSITY DRACO_FIXTURES WORKDIR
set -euo pipefail
radiosity=$1 fixtures=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
"$fixtures" "$work"
for file in plain draco draco-11bit; do
  "$radiosity" viewfactors "$work/$file.glb" --rays 200000 --output "$work/$file.csv" 2>/dev/null
done
cmp "$work/plain.csv" "$work/draco.csv" || { echo "FAIL: lossless Draco gives other view factors"; exit 1; }
echo "ok   lossless Draco: the plain file's view factors, byte for byte"
python3 - "$work/plain.csv" "$work/draco-11bit.csv" <<'PY'
import csv, math, sys
a, b = ({(r["from"], r["to"]): (float(r["F"]), float(r["stderr"])) for r in csv.DictReader(open(p))} for p in sys.argv[1:3])
assert a.keys() == b.keys() and a, (a, b)
for k in a:
    (fa, sa), (fb, sb) = a[k], b[k]
    assert abs(fa - fb) <= 4 * math.hypot(sa, sb), (k, a[k], b[k])
print("ok   11-bit Draco: view factors within four standard errors of the plain file's (%s)" %
      ", ".join("%s->%s %.4f/%.4f" % (f, t, a[(f, t)][0], b[(f, t)][0]) for f, t in a))
PY
for case in "draco-bad-attribute:attribute 77" "draco-corrupt:cannot be decoded"; do
  file=${case%%:*} problem=${case#*:}
  status=0
  "$radiosity" viewfactors "$work/$file.glb" --output "$work/$file.csv" 2>"$work/stderr" || status=$?
  [ "$status" -eq 2 ] || { echo "FAIL $file: exit status $status, expected 2"; cat "$work/stderr"; exit 1; }
  grep -q "$file.glb" "$work/stderr" && grep -q "$problem" "$work/stderr" ||
    { echo "FAIL $file: the message does not name the file and '$problem'"; cat "$work/stderr"; exit 1; }
  [ ! -e "$work/$file.csv" ] || { echo "FAIL $file: left an output file"; exit 1; }
  echo "ok   $file: $(cat "$work/stderr")"
done
# COLOR_0 inside the compressed data: the same image as from the plain file's accessor, which
# differs from the uncoloured quads'.
for file in plain plain-coloured draco-coloured; do
  "$radiosity" solve "$work/$file.glb" --sky 1,1,1 --width 32 --height 32 --render radiosity --seed 1 --rays 1e5 \
    --output "$work/out-$file" --quiet 2>/dev/null
done
cmp -s "$work/out-plain-coloured/render.exr" "$work/out-draco-coloured/render.exr" ||
  { echo "FAIL: Draco-compressed COLOR_0 gives another image than the plain file's"; exit 1; }
if cmp -s "$work/out-plain/render.exr" "$work/out-plain-coloured/render.exr"; then
  echo "FAIL: COLOR_0 changed nothing"; exit 1
fi
echo "ok   Draco-compressed COLOR_0: the plain file's image, byte for byte"
