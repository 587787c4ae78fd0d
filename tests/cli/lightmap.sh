#!/usr/bin/env bash
# `radiosity solve --lightmap` end to end: its files and report; the same lightmap bits on 1 and 2
# PoCL threads; lightmapped.glb rendered by the project's own camera pass (its surfaces show only
# their emissive lightmap, as in a plain glTF viewer) matches the solve's render
# (lightmapped_render.py); and bad lightmap options are refused before any output is written.
# Usage: lightmap.sh RADIOSITY SCENE WORKDIR
set -euo pipefail
radiosity=$1 scene=$2 work=$3
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work" && mkdir -p "$work"
common=(--rays 300000 --render direct --width 96 --height 96 --samples 4 --seed 3 --quiet
        --lightmap --lightmap-size 256 --lightmap-samples 16)
for threads in 1 2; do
  POCL_MAX_PTHREAD_COUNT=$threads "$radiosity" solve "$scene" "${common[@]}" --output "$work/t$threads" 2>/dev/null
  for f in lightmap.exr lightmap.png lightmapped.glb report.json; do
    [ -s "$work/t$threads/$f" ] || { echo "missing $f"; exit 1; }
  done
done
for f in lightmap.exr lightmapped.glb; do
  cmp "$work/t1/$f" "$work/t2/$f" || { echo "$f differs between 1 and 2 threads"; exit 1; }
done
grep -q '"lightmap": {' "$work/t1/report.json" || { echo "report: no lightmap section"; exit 1; }
grep -q '"uv": "atlas"' "$work/t1/report.json" || { echo "report: no TEXCOORD_1 here, so an atlas"; exit 1; }
strength=$(/usr/bin/python3 -c \
  "import json, sys; print(json.load(open(sys.argv[1]))['lightmap']['emissive_strength'])" "$work/t1/report.json")
# --lightmap-radiance adds the radiance pages.
"$radiosity" solve "$scene" "${common[@]}" --lightmap-radiance --output "$work/radiance" 2>/dev/null
[ -s "$work/radiance/lightmap-radiance.exr" ] || { echo "--lightmap-radiance: no lightmap-radiance.exr"; exit 1; }

# The lightmapped scene, from the same camera, in the same mode.
"$radiosity" solve "$work/t1/lightmapped.glb" --rays 100000 --render direct --width 96 --height 96 --samples 4 \
  --seed 3 --quiet --output "$work/lightmapped" 2>/dev/null
/usr/bin/python3 "$here/lightmapped_render.py" "$work/t1/render.exr" "$work/lightmapped/render.exr" "$strength"

# Refusals: no partial output, a message naming the problem, a non-zero status.
refuse() {  # expected text, then the arguments
  local expect=$1
  shift
  rm -rf "$work/refused"
  if "$radiosity" solve "$@" --output "$work/refused" --quiet 2>"$work/refused.err"; then
    echo "accepted: $*"; exit 1
  fi
  grep -q "$expect" "$work/refused.err" || { echo "no '$expect' in:"; cat "$work/refused.err"; exit 1; }
  [ ! -e "$work/refused" ] || { echo "output written for: $*"; exit 1; }
}
refuse "TEXCOORD_1" "$scene" --rays 1000 --lightmap --lightmap-uv scene
refuse "lightmap" "$scene" --rays 1000 --texel-size 0.01
refuse "of surface .* larger than a page" "$scene" --rays 1000 --lightmap --texel-size 1e-7 --lightmap-size 8
echo "lightmap: outputs, determinism, the lightmapped render and refusals as expected"
