#!/usr/bin/env bash
# Long runs: SIGINT stops a solve at the next batch with a complete output set marked
# "interrupted"; a solve stopped part-way (here by --time-limit) and resumed from its
# checkpoint ends with bitwise the same radiosities as the uninterrupted solve.
# Usage: interrupt_resume.sh RADIOSITY SCENE WORKDIR
set -uo pipefail
radiosity=$1 scene=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }
surfaces() { awk '/^  "surfaces": \[/{on=1} on{print} on&&/^  \],?$/{exit}' "$1"; }
common=(--rays 4e6 --patch-size 0.03 --width 32 --height 32 --seed 4 --quiet)

# 1. SIGINT: a solve that would run for a long time stops and writes everything. Ten times the
# rays of the others, with tolerance 1e-7: the others' 4e6 rays reached 1e-7 in 2.0 s on a fast
# 2-core machine, as long as the wait before the signal.
long=(--rays 4e7 --patch-size 0.03 --width 32 --height 32 --seed 4 --quiet)
"$radiosity" solve "$scene" "${long[@]}" --tolerance 1e-7 --output "$work/interrupted" 2>"$work/interrupted.log" &
pid=$!
sleep 2
kill -INT $pid
wait $pid
status=$?
[ $status -eq 0 ] || fail "interrupted solve exited with $status: $(cat "$work/interrupted.log")"
for f in render.exr render.png lit.glb report.json; do [ -s "$work/interrupted/$f" ] || fail "interrupted: missing $f"; done
grep -q '"stopped": "interrupted"' "$work/interrupted/report.json" || fail "report not marked interrupted"
echo "ok: SIGINT gave a complete output set marked interrupted"

# 2. Resume: stop part-way with a checkpoint, continue from it, compare with one straight run.
"$radiosity" solve "$scene" "${common[@]}" --output "$work/straight" 2>/dev/null || fail "straight solve"
"$radiosity" solve "$scene" "${common[@]}" --time-limit 0.3 --checkpoint "$work/state.ckpt" \
  --output "$work/part" 2>/dev/null || fail "partial solve"
grep -q '"stopped": "time-limit"' "$work/part/report.json" || fail "the partial solve was not stopped by its time limit"
[ -s "$work/state.ckpt" ] || fail "no checkpoint written"
"$radiosity" solve "$scene" "${common[@]}" --resume "$work/state.ckpt" --output "$work/resumed" 2>/dev/null || fail "resumed solve"
surfaces "$work/straight/report.json" > "$work/straight.surfaces"
surfaces "$work/resumed/report.json" > "$work/resumed.surfaces"
[ "$(wc -l < "$work/straight.surfaces")" -gt 20 ] || fail "no surfaces in the report"
cmp "$work/straight.surfaces" "$work/resumed.surfaces" || fail "resumed radiosities differ from the straight run's"
grep '"shots"' "$work/straight/report.json" > "$work/a"; grep '"shots"' "$work/resumed/report.json" > "$work/b"
cmp -s "$work/a" "$work/b" || fail "resumed shot count differs"
echo "ok: resumed from $(grep -o '"shots": [0-9]*' "$work/part/report.json") to bitwise the straight run's radiosities"

# 2b. The same with two levels (elements finer than patches: the checkpoint holds per-element
# and per-patch arrays of different lengths).
two=(--element-size 0.015)
"$radiosity" solve "$scene" "${common[@]}" "${two[@]}" --output "$work/straight2" 2>/dev/null || fail "two-level solve"
"$radiosity" solve "$scene" "${common[@]}" "${two[@]}" --time-limit 0.3 --checkpoint "$work/two.ckpt" \
  --output "$work/part2" 2>/dev/null || fail "partial two-level solve"
grep -q '"stopped": "time-limit"' "$work/part2/report.json" || fail "the partial two-level solve was not stopped"
"$radiosity" solve "$scene" "${common[@]}" "${two[@]}" --resume "$work/two.ckpt" --output "$work/resumed2" \
  2>"$work/resumed2.log" || fail "resumed two-level solve: $(cat "$work/resumed2.log")"
surfaces "$work/straight2/report.json" > "$work/straight2.surfaces"
surfaces "$work/resumed2/report.json" > "$work/resumed2.surfaces"
cmp "$work/straight2.surfaces" "$work/resumed2.surfaces" || fail "resumed two-level radiosities differ"
echo "ok: a two-level solve resumed to bitwise the straight run's radiosities"

# 3. A checkpoint of another problem, or a damaged one, is refused (exit status 2).
"$radiosity" solve "$scene" "${common[@]}" --min-rays 64 --resume "$work/state.ckpt" --output "$work/other" 2>"$work/other.log"
[ $? -eq 2 ] && grep -q "another problem" "$work/other.log" || fail "a checkpoint of other options was not refused: $(cat "$work/other.log")"
head -c 1000 "$work/state.ckpt" > "$work/damaged.ckpt"
"$radiosity" solve "$scene" "${common[@]}" --resume "$work/damaged.ckpt" --output "$work/damaged" 2>"$work/damaged.log"
[ $? -eq 2 ] && grep -qi "damaged\|truncated" "$work/damaged.log" || fail "a damaged checkpoint was not refused: $(cat "$work/damaged.log")"
[ ! -e "$work/damaged/report.json" ] || fail "outputs written despite a refused checkpoint"
echo "ok: foreign and damaged checkpoints refused"
