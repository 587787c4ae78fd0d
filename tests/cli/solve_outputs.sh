#!/usr/bin/env bash
# `radiosity solve` end to end: the four outputs exist, no temporary files are left, the
# report says why it stopped; and the same seed gives bitwise identical surface radiosities
# with 1 and 2 PoCL threads.
# Usage: solve_outputs.sh RADIOSITY SCENE WORKDIR
set -euo pipefail
radiosity=$1 scene=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
surfaces() {  # the "surfaces" array of a report: every line from its key to its closing bracket
  awk '/^  "surfaces": \[/{on=1} on{print} on&&/^  \],?$/{exit}' "$1"
}
for threads in 1 2; do
  POCL_MAX_PTHREAD_COUNT=$threads "$radiosity" solve "$scene" --output "$work/t$threads" --rays 300000 \
    --patch-size 0.06 --width 64 --height 48 --seed 5 --quiet 2>"$work/stderr-$threads"
  for f in render.exr render.png lit.glb report.json; do
    [ -s "$work/t$threads/$f" ] || { echo "missing $f"; exit 1; }
  done
  if ls "$work/t$threads" | grep -q tmp; then echo "temporary file left: $(ls "$work/t$threads")"; exit 1; fi
  grep -q '"stopped": "tolerance"' "$work/t$threads/report.json" || { echo "report: no stop reason"; exit 1; }
  [ "$(wc -l < "$work/stderr-$threads")" -eq 1 ] || { echo "expected one summary line:"; cat "$work/stderr-$threads"; exit 1; }
  surfaces "$work/t$threads/report.json" > "$work/surfaces-$threads.json"
done
[ "$(wc -l < "$work/surfaces-1.json")" -gt 20 ] || { echo "no surfaces in the report"; exit 1; }
cmp "$work/surfaces-1.json" "$work/surfaces-2.json" || { diff "$work/surfaces-1.json" "$work/surfaces-2.json" | head; exit 1; }
echo "outputs complete; radiosities identical with 1 and 2 threads"
