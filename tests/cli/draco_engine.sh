#!/usr/bin/env bash
# A Draco-compressed model from another project: the Khronos 2CylinderEngine as Debian's
# assimp-testmodels ships it, compressed and not. Draco stored its positions at 11 bits per mesh
# (vertices moved by up to 4e-4 of each mesh's size), and where this engine's parts touch, that
# moves their view factors far beyond the noise of the rays. So the compressed file is held to
# the uncompressed one with its positions quantized the same way (tests/tools/quantize_gltf.py):
# every pair within five standard errors of the difference, with other seeds. Then the
# surfaces, their areas and the share of rays each loses are the same too.
# Usage: draco_engine.sh RADIOSITY SOURCE_DIR WORKDIR
set -euo pipefail
radiosity=$1 source=$2 work=$3
models=/usr/share/assimp/models/glTF2
draco=$models/draco/2CylinderEngine.gltf plain=$models/2CylinderEngine-glTF-Binary/2CylinderEngine.glb
for f in "$draco" "$plain"; do
  [ -f "$f" ] || { echo "FAIL: $f is missing: install assimp-testmodels (scripts/setup.sh does)"; exit 1; }
done
rm -rf "$work" && mkdir -p "$work"
python3 "$source/tests/tools/quantize_gltf.py" "$plain" 11 "$work/quantized.gltf"
"$radiosity" viewfactors "$draco" --rays 100000 --enforce none --seed 1 --output "$work/draco.csv" \
  --to-space "$work/draco-space.csv" 2>"$work/draco.log" || { cat "$work/draco.log"; exit 1; }
"$radiosity" viewfactors "$work/quantized.gltf" --rays 100000 --enforce none --seed 2 --output "$work/quantized.csv" \
  --to-space "$work/quantized-space.csv" 2>"$work/quantized.log" || { cat "$work/quantized.log"; exit 1; }
python3 - "$work" <<'PY'
import csv, math, sys
work = sys.argv[1]
def table(name):
    return {(r["from"], r["to"]): (float(r["F"]), float(r["stderr"])) for r in csv.DictReader(open(f"{work}/{name}.csv"))}
def space(name):
    return {r["from"]: (float(r["area"]), float(r["to_space"]), float(r["stderr"])) for r in csv.DictReader(open(f"{work}/{name}-space.csv"))}
a, b = table("draco"), table("quantized")
sa, sb = space("draco"), space("quantized")
assert sa.keys() == sb.keys() and len(sa) == 67, (len(sa), len(sb))
worst, beyond4 = 0.0, 0
for k in a.keys() | b.keys():
    (fa, ea), (fb, eb) = a.get(k, (0.0, 0.0)), b.get(k, (0.0, 0.0))
    sigma = math.hypot(ea, eb)
    if sigma == 0.0:
        # F = 1 in both runs (a missing entry has no error of its own, but the other run's is then > 0)
        assert abs(fa - fb) <= 2e-5, (k, fa, fb)
        continue
    z = abs(fa - fb) / sigma
    worst, beyond4 = max(worst, z), beyond4 + (z > 4)
    assert z <= 5, f"{k[0]}->{k[1]}: {fa} (Draco) vs {fb} (quantized .glb), {z:.1f} standard errors"
for s in sa:
    (area_a, lost_a, ea), (area_b, lost_b, eb) = sa[s], sb[s]
    assert abs(area_a - area_b) <= 2e-3 * area_b, (s, area_a, area_b)   # 11-bit positions
    assert abs(lost_a - lost_b) <= 5 * math.hypot(ea, eb) + 1e-12, (s, lost_a, lost_b)
print(f"ok   Draco 2CylinderEngine: {len(a | b)} pairs and {len(sa)} shares to space agree with the .glb "
      f"quantized to 11 bits (largest difference {worst:.1f} standard errors, {beyond4} beyond 4)")
PY
