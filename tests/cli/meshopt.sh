#!/usr/bin/env bash
# EXT_meshopt_compression as users meet it (gltfpack and glTF-Transform write it for the web):
# the Cornell box with every buffer view compressed by libmeshoptimizer's own encoders
# (tests/tools/meshopt_fixtures.cpp). Attributes and index sequences are exact, so the
# compressed file gives the plain file's view factors byte for byte; the triangle codec may
# rotate a triangle's corners (its patches then lie differently), and the exponential filter
# rounds positions to 12-bit mantissas, so those agree within four standard errors. A broken
# property of each kind is refused with exit status 2, naming the file, the buffer view and the
# problem, and nothing is written.
# Usage: meshopt.sh RADIOSITY MESHOPT_FIXTURES SCENE.gltf WORKDIR
set -euo pipefail
radiosity=$1 fixtures=$2 scene=$3 work=$4
rm -rf "$work" && mkdir -p "$work"
"$fixtures" "$scene" "$work"
cp "$scene" "$work/plain.gltf"
for file in plain.gltf exact.gltf triangles.glb lossy.gltf; do
  "$radiosity" viewfactors "$work/$file" --rays 100000 --output "$work/$file.csv" 2>/dev/null
done
cmp "$work/plain.gltf.csv" "$work/exact.gltf.csv" || { echo "FAIL: exact meshopt gives other view factors"; exit 1; }
echo "ok   attributes and index sequences: the plain file's view factors, byte for byte"
for file in triangles.glb lossy.gltf; do
python3 - "$work/plain.gltf.csv" "$work/$file.csv" "$file" <<'PY'
import csv, math, sys
a, b = ({(r["from"], r["to"]): (float(r["F"]), float(r["stderr"])) for r in csv.DictReader(open(p))} for p in sys.argv[1:3])
# A pair one file lists and the other does not (a single ray, where moved corners open a gap)
# counts as 0 there, with the other file's standard error.
assert a and len(set(a) ^ set(b)) <= 2, (sorted(set(a) ^ set(b)))
worst = max(abs(a.get(k, (0, 0))[0] - b.get(k, (0, 0))[0]) /
            math.hypot(a.get(k, (0, 0))[1], b.get(k, (0, 0))[1]) for k in set(a) | set(b))
assert worst <= 4, (sys.argv[3], worst)
print("ok   %s: %d view factors within four standard errors of the plain file's (largest %.2f)" % (sys.argv[3], len(set(a) | set(b)), worst))
PY
done
cmp -s "$work/plain.gltf.csv" "$work/lossy.gltf.csv" && { echo "FAIL: 12-bit positions gave the exact file's bits: the filter was not applied"; exit 1; }
for case in "bad-cut:bufferViews[0]: the EXT_meshopt_compression data cannot be decoded" \
            "bad-count:differs from the buffer view's byteLength" \
            "bad-mode:mode 'TRIANGLE_STRIP' is none of ATTRIBUTES, TRIANGLES, INDICES" \
            "bad-filter:the QUATERNION filter needs byteStride 8" \
            "bad-offset:run past the end of buffer 0" \
            "bad-huge:more than the codec can hold"; do
  file=${case%%:*} problem=${case#*:}
  status=0
  "$radiosity" viewfactors "$work/$file.gltf" --output "$work/$file.csv" 2>"$work/stderr" || status=$?
  [ "$status" -eq 2 ] || { echo "FAIL $file: exit status $status, expected 2"; cat "$work/stderr"; exit 1; }
  grep -qF "$file.gltf" "$work/stderr" && grep -qF "$problem" "$work/stderr" ||
    { echo "FAIL $file: the message does not name the file and '$problem'"; cat "$work/stderr"; exit 1; }
  [ ! -e "$work/$file.csv" ] || { echo "FAIL $file: left an output file"; exit 1; }
  echo "ok   $file: $(cat "$work/stderr")"
done
