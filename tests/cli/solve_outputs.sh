#!/usr/bin/env bash
# `radiosity solve` end to end: the four outputs exist, no temporary files are left, the
# report says why it stopped; and the same seed gives bitwise identical surface radiosities
# with 1 and 2 PoCL threads, as do the direct and final-gather camera passes and the path tracer;
# and solves that carry light through mirrors and glass (SPECULAR_SCENE ...: the shots, and the
# rays drawn from punctual lights) give the same radiosities and image bits on 1 and 2 threads.
# Usage: solve_outputs.sh RADIOSITY SCENE WORKDIR [SPECULAR_SCENE ...]
set -euo pipefail
radiosity=$1 scene=$2 work=$3
shift 3
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
# The camera pass's sampled modes and the path tracer: the same image bits on 1 and 2 threads.
for mode in direct final-gather; do
  for threads in 1 2; do
    POCL_MAX_PTHREAD_COUNT=$threads "$radiosity" solve "$scene" --output "$work/$mode-$threads" --rays 100000 \
      --patch-size 0.1 --width 24 --height 20 --samples 64 --render $mode --seed 5 --quiet 2>/dev/null
  done
  cmp "$work/$mode-1/render.exr" "$work/$mode-2/render.exr" || { echo "--render $mode: images differ"; exit 1; }
  grep -q "\"mode\": \"$mode\"" "$work/$mode-1/report.json" || { echo "--render $mode: not in the report"; exit 1; }
done
# --gather-rays reaches the direct mode's gather (fewer rays: another image), and 0 is refused.
"$radiosity" solve "$scene" --output "$work/gather-16" --rays 100000 --patch-size 0.1 --width 24 --height 20 \
  --samples 64 --render direct --seed 5 --gather-rays 16 --quiet 2>/dev/null
! cmp -s "$work/direct-1/render.exr" "$work/gather-16/render.exr" || { echo "--gather-rays 16: the same image"; exit 1; }
status=0
"$radiosity" solve "$scene" --output "$work/gather-0" --render direct --gather-rays 0 --quiet 2>"$work/gather-0.log" ||
  status=$?
[ $status -eq 2 ] && grep -q "gather-rays" "$work/gather-0.log" && [ ! -e "$work/gather-0" ] ||
  { echo "--gather-rays 0: exit status $status, $(cat "$work/gather-0.log")"; exit 1; }
for threads in 1 2; do
  POCL_MAX_PTHREAD_COUNT=$threads "$radiosity" pathtrace "$scene" --output "$work/pt-$threads.exr" --width 24 \
    --height 20 --samples 64 --seed 5 2>/dev/null
done
cmp "$work/pt-1.exr" "$work/pt-2.exr" || { echo "pathtrace: images differ"; exit 1; }
for specular in "$@"; do
  for threads in 1 2; do
    POCL_MAX_PTHREAD_COUNT=$threads "$radiosity" solve "$specular" --output "$work/specular-$threads" --rays 300000 \
      --patch-size 0.06 --width 32 --height 32 --seed 5 --quiet 2>/dev/null
    surfaces "$work/specular-$threads/report.json" > "$work/specular-surfaces-$threads.json"
  done
  cmp "$work/specular-surfaces-1.json" "$work/specular-surfaces-2.json" ||
    { echo "$specular: radiosities differ"; exit 1; }
  cmp "$work/specular-1/render.exr" "$work/specular-2/render.exr" || { echo "$specular: images differ"; exit 1; }
done
echo "outputs complete; radiosities, sampled camera passes and path-traced images identical with 1 and 2 threads"
