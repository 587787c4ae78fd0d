#!/usr/bin/env bash
# The same results on 1, 2 and 3 MPI ranks (3 oversubscribed on a 2-core machine: a check of
# correctness, not speed), bitwise: surface view factors (also to a target error), patch view
# factors, heat exchange, and solves by the
# progressive strategy (plain, adaptive with elements, with mirrors and glass) and the matrix
# strategy; a solve stopped on
# 2 ranks and resumed on 3; and failures: a bad scene, a rank without its device, a rank killed
# part-way, each ending every rank with a message naming the rank, no output, and the last
# checkpoint whole. Skips (77) without mpirun or when radiosity was built without MPI.
# Usage: mpi.sh RADIOSITY SOURCE_DIR WORKDIR
set -uo pipefail
radiosity=$1 source=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
command -v mpirun >/dev/null || { echo "no mpirun: skipped"; exit 77; }
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1  # CI runs as root
fail() { echo "FAIL: $*"; exit 1; }
# signal_rank_1 SIGNAL OUTPUT: sends SIGNAL to the rank-1 process of the run writing OUTPUT
# (Open MPI puts the rank in each process's environment); fails if there is none.
signal_rank_1() {
  local pid sent=1
  for pid in $(pgrep -f -- "--output $2"); do
    if tr '\0' '\n' < "/proc/$pid/environ" 2>/dev/null | grep -qx 'OMPI_COMM_WORLD_RANK=1'; then
      kill -"$1" "$pid" && sent=0
    fi
  done
  return $sent
}
scene="$source/scenes/cornell-box.gltf"

"$radiosity" viewfactors "$scene" --rays 20000 --seed 4 --output "$work/one.csv" 2>/dev/null || fail "one process"
"$radiosity" viewfactors "$scene" --rays 20000 --seed 4 --format mtx --output "$work/one.mtx" 2>/dev/null ||
  fail "one process, mtx"
timeout 300 mpirun -np 2 "$radiosity" viewfactors "$scene" --rays 20000 --seed 4 --output "$work/two.csv" \
  2>"$work/stderr" || { cat "$work/stderr"; fail "mpirun -np 2"; }
if ! grep -q "from 2 ranks" "$work/stderr"; then
  echo "radiosity was built without MPI (no 'from 2 ranks' in its summary): skipped"
  exit 77
fi
cmp "$work/one.csv" "$work/two.csv" || fail "2 ranks differ from one process"
echo "ok   2 ranks: bitwise the CSV of one process"
timeout 300 mpirun -np 3 --oversubscribe "$radiosity" viewfactors "$scene" --rays 20000 --seed 4 --format mtx \
  --output "$work/three.mtx" 2>"$work/stderr" || { cat "$work/stderr"; fail "mpirun -np 3"; }
cmp "$work/one.mtx" "$work/three.mtx" || fail "3 ranks differ from one process"
echo "ok   3 ranks (oversubscribed): bitwise the Matrix Market file of one process"

timeout 300 mpirun -np 2 "$radiosity" viewfactors "$source/tests/data/bad/node-cycle.gltf" --rays 2000 \
  --output "$work/bad.csv" >/dev/null 2>"$work/stderr"
status=$?
[ "$status" -eq 2 ] || { cat "$work/stderr"; fail "a bad scene under mpirun: status $status, expected 2"; }
grep -q "error (rank [01] of 2): .*node-cycle.gltf" "$work/stderr" || fail "no message naming the rank and the file"
[ ! -e "$work/bad.csv" ] || fail "a bad scene under mpirun left an output"
echo "ok   a bad scene under mpirun: status 2, the rank named, no output"

# solve: every strategy's result on N ranks is bitwise that of one process (image, baked model,
# the report's surfaces); the report names the ranks and their devices.
# report.json without what may differ from run to run or with the number of processes.
results() {
  python3 -c '
import json, sys
r = json.load(open(sys.argv[1]))
for key in ("seconds", "processes", "device"): r.pop(key, None)
r["solve"].pop("rays_per_second", None)
print(json.dumps(r, indent=1, sort_keys=True))' "$1"
}
same_solve() {  # same_solve NAME DIR_ONE DIR_N
  for f in render.exr lit.glb; do cmp -s "$2/$f" "$3/$f" || fail "$1: $f differs from one process"; done
  results "$2/report.json" > "$work/one.results"; results "$3/report.json" > "$work/n.results"
  grep -q '"relative_residual"' "$work/one.results" && [ "$(wc -l < "$work/one.results")" -gt 60 ] ||
    fail "$1: no radiosities or energy in the report"
  cmp -s "$work/one.results" "$work/n.results" ||
    { diff "$work/one.results" "$work/n.results" | head; fail "$1: the report (radiosities, energy, counts) differs from one process"; }
}
image=(--width 32 --height 32 --quiet)
solve_on() {  # solve_on RANKS OUTPUT ARGS...: one process for RANKS 1
  local ranks=$1 out=$2; shift 2
  if [ "$ranks" -eq 1 ]; then "$radiosity" solve "$scene" "${image[@]}" --output "$out" "$@" 2>"$work/stderr"
  else timeout 300 mpirun -np "$ranks" --oversubscribe "$radiosity" solve "$scene" "${image[@]}" --output "$out" "$@" \
    2>"$work/stderr"; fi || { cat "$work/stderr"; fail "solve on $ranks ranks: $*"; }
}
progressive=(--rays 2e6 --seed 4)
solve_on 1 "$work/solve-1" "${progressive[@]}"
solve_on 2 "$work/solve-2" "${progressive[@]}"
same_solve "progressive, 2 ranks" "$work/solve-1" "$work/solve-2"
python3 -c '
import json, sys
p = json.load(open(sys.argv[1]))["processes"]
sys.exit(0 if p["count"] == 2 and len(p["devices"]) == 2 and all(p["devices"]) else 1)' "$work/solve-2/report.json" ||
  fail "the report does not count 2 ranks and name each one's device"
echo "ok   solve, progressive, 2 ranks: bitwise one process's image, model and radiosities; the report names both ranks' devices"
# An overshooting solve (reflectance 0.99, solver/amplification.h): signed counts summed alike.
furnace=("$source/tests/data/solve/white-furnace-0.99.gltf" --patch-size 0.25 --rays 5e5 --tolerance 1e-3 --seed 6)
"$radiosity" solve "${furnace[@]}" "${image[@]}" --output "$work/furnace-1" 2>/dev/null || fail "furnace, one process"
timeout 300 mpirun -np 2 "$radiosity" solve "${furnace[@]}" "${image[@]}" --output "$work/furnace-2" 2>"$work/stderr" ||
  { cat "$work/stderr"; fail "furnace on 2 ranks"; }
grep -q '"ray_power_scale"' "$work/furnace-1/report.json" || fail "the furnace did not overshoot: nothing to compare"
same_solve "overshooting furnace, 2 ranks" "$work/furnace-1" "$work/furnace-2"
echo "ok   an overshooting solve (reflectance 0.99) on 2 ranks: bitwise one process's"
# Mirrors and glass (kernels/shoot.cl's walk through them, specular_walk.h): the power they pass on, and the caustic
# columns the final gather reads, summed alike.
specular=("$source/scenes/cornell-box-specular.gltf" --patch-size 0.1 --rays 3e5 --seed 3 --render final-gather)
"$radiosity" solve "${specular[@]}" "${image[@]}" --output "$work/specular-1" 2>/dev/null || fail "specular, one process"
timeout 300 mpirun -np 2 "$radiosity" solve "${specular[@]}" "${image[@]}" --output "$work/specular-2" \
  2>"$work/stderr" || { cat "$work/stderr"; fail "specular on 2 ranks"; }
same_solve "mirrors and glass, 2 ranks" "$work/specular-1" "$work/specular-2"
echo "ok   mirrors and glass on 2 ranks: bitwise one process's radiosities and final-gather image"
adaptive=(--rays 1e6 --seed 2 --adaptive --element-size 0.06)
solve_on 1 "$work/adaptive-1" "${adaptive[@]}"
solve_on 3 "$work/adaptive-3" "${adaptive[@]}"
same_solve "adaptive, 3 ranks" "$work/adaptive-1" "$work/adaptive-3"
echo "ok   solve, adaptive with elements, 3 ranks (oversubscribed): bitwise one process's"
matrix=(--method hemicube --solver gauss-seidel --patch-size 0.15)
solve_on 1 "$work/matrix-1" "${matrix[@]}"
solve_on 2 "$work/matrix-2" "${matrix[@]}"
same_solve "hemicube matrix, 2 ranks" "$work/matrix-1" "$work/matrix-2"
"$radiosity" viewfactors "$scene" --level patch --patch-size 0.2 --rays-per-patch 2000 --seed 3 --format mtx \
  --output "$work/patch-1.mtx" 2>/dev/null || fail "patch view factors, one process"
timeout 300 mpirun -np 3 --oversubscribe "$radiosity" viewfactors "$scene" --level patch --patch-size 0.2 --rays-per-patch 2000 \
  --seed 3 --format mtx --output "$work/patch-3.mtx" 2>"$work/stderr" || { cat "$work/stderr"; fail "patch view factors on 3 ranks"; }
cmp -s "$work/patch-1.mtx" "$work/patch-3.mtx" || fail "patch-level view factors on 3 ranks differ from one process"
echo "ok   matrix rows divided among ranks: hemicube + Gauss-Seidel on 2 and patch view factors on 3, bitwise one process's"
# --max-memory refuses where one process refuses, with its figures (every rank checks the
# batches in order), and lets through what one process lets through.
guarded=(viewfactors "$scene" --level patch --patch-size 0.2 --rays-per-patch 2000 --seed 3 --max-memory 251500)
"$radiosity" "${guarded[@]}" --output "$work/guard-1.csv" 2>"$work/guard-1.err"
status_one=$?
timeout 300 mpirun -np 3 --oversubscribe "$radiosity" "${guarded[@]}" --output "$work/guard-3.csv" 2>"$work/guard-3.err"
status_three=$?
if [ "$status_one" -eq 0 ]; then
  [ "$status_three" -eq 0 ] && cmp -s "$work/guard-1.csv" "$work/guard-3.csv" || fail "--max-memory: 3 ranks did not let through what one process did"
else
  one=$(sed -n 's/^radiosity: error: //p' "$work/guard-1.err")
  grep -qF "$one" "$work/guard-3.err" || { cat "$work/guard-3.err"; fail "--max-memory: 3 ranks refused otherwise than one process ($one)"; }
  [ "$status_three" -eq "$status_one" ] && [ ! -e "$work/guard-3.csv" ] || fail "--max-memory: 3 ranks gave status $status_three"
fi
echo "ok   --max-memory on 3 ranks: the same decision and figures as one process"

# Surface view factors to a target error (rounds), and heat exchange (batches): divided, bitwise.
"$radiosity" viewfactors "$scene" --target-error 0.002 --seed 5 --output "$work/target-1.csv" 2>"$work/stderr" ||
  { cat "$work/stderr"; fail "--target-error, one process"; }
grep -q "in [2-9] rounds" "$work/stderr" || { cat "$work/stderr"; fail "--target-error took one round: no rounds to divide"; }
timeout 300 mpirun -np 2 "$radiosity" viewfactors "$scene" --target-error 0.002 --seed 5 --output "$work/target-2.csv" \
  2>"$work/stderr" || { cat "$work/stderr"; fail "--target-error on 2 ranks"; }
cmp -s "$work/target-1.csv" "$work/target-2.csv" || fail "--target-error on 2 ranks differs from one process"
spheres="$source/tests/data/thermal/concentric-spheres.gltf" properties="$source/tests/data/thermal/spheres.csv"
"$radiosity" exchange "$spheres" --properties "$properties" --rays 40000 --output "$work/heat-1.csv" \
  --exchange "$work/gebhart-1.csv" 2>/dev/null || fail "exchange, one process"
timeout 300 mpirun -np 3 --oversubscribe "$radiosity" exchange "$spheres" --properties "$properties" --rays 40000 \
  --output "$work/heat-3.csv" --exchange "$work/gebhart-3.csv" 2>"$work/stderr" || { cat "$work/stderr"; fail "exchange on 3 ranks"; }
cmp -s "$work/heat-1.csv" "$work/heat-3.csv" && cmp -s "$work/gebhart-1.csv" "$work/gebhart-3.csv" ||
  fail "exchange on 3 ranks differs from one process"
echo "ok   viewfactors --target-error on 2 ranks and exchange on 3: bitwise one process's"

# Interrupted on 2 ranks (time limit), resumed on 3: bitwise the straight solve of one process.
solve_on 2 "$work/part-2" "${progressive[@]}" --time-limit 0.3 --checkpoint "$work/state.ckpt"
grep -q '"stopped": "time-limit"' "$work/part-2/report.json" || fail "the partial solve on 2 ranks was not stopped by its time limit"
solve_on 3 "$work/resumed-3" "${progressive[@]}" --resume "$work/state.ckpt"
same_solve "2 ranks, resumed on 3" "$work/solve-1" "$work/resumed-3"
echo "ok   stopped on 2 ranks, resumed on 3: bitwise the straight solve of one process"

# SIGTERM to rank 1 alone: both ranks stop at the same batch and rank 0 writes a whole output set.
# 25 times the rays of the others: their 2e6 rays reached 1e-7 in 1.7 s on a fast 2-core machine,
# before the signal.
timeout 300 mpirun -np 2 "$radiosity" solve "$scene" "${image[@]}" --rays 5e7 --seed 4 --tolerance 1e-7 \
  --output "$work/term" >/dev/null 2>"$work/stderr" &
launcher=$!
sleep 3
signalled=0
signal_rank_1 TERM "$work/term" && signalled=1
wait $launcher
status=$?
[ "$signalled" -eq 1 ] || fail "found no rank 1 to signal"
[ "$status" -eq 0 ] || { cat "$work/stderr"; fail "SIGTERM to rank 1: status $status, expected 0"; }
grep -q '"stopped": "interrupted"' "$work/term/report.json" || fail "SIGTERM to rank 1: the report is not marked interrupted"
for f in render.exr render.png lit.glb; do [ -s "$work/term/$f" ] || fail "SIGTERM to rank 1: no $f"; done
echo "ok   SIGTERM to rank 1 alone: both ranks stopped at one batch, a whole output set marked interrupted"

# A rank whose device cannot be had: one message naming the rank and the cause, no output.
timeout 300 mpirun -np 2 "$radiosity" solve "$scene" "${image[@]}" "${progressive[@]}" --device 0,no-such-device \
  --output "$work/no-device" >/dev/null 2>"$work/stderr"
status=$?
[ "$status" -eq 2 ] || { cat "$work/stderr"; fail "a rank without its device: status $status, expected 2"; }
grep -q "error (rank 1 of 2): device 'no-such-device': no device matches" "$work/stderr" ||
  { cat "$work/stderr"; fail "no message naming rank 1 and its device"; }
[ ! -e "$work/no-device" ] || fail "a rank without its device left an output"
echo "ok   rank 1 without its device: status 2, the rank and the device named, no output"

# A rank killed part-way: the run ends with a status that says so and Open MPI's line naming the
# rank, no output; the last checkpoint is whole and resumes to the straight result.
timeout 300 mpirun -np 2 "$radiosity" solve "$scene" "${image[@]}" "${progressive[@]}" --tolerance 1e-7 \
  --checkpoint "$work/killed.ckpt" --checkpoint-every 0.1 --output "$work/killed" >/dev/null 2>"$work/stderr" &
launcher=$!
for _ in $(seq 300); do [ -s "$work/killed.ckpt" ] && break; sleep 0.1; done
[ -s "$work/killed.ckpt" ] || fail "no checkpoint before the kill"
killed=0
signal_rank_1 KILL "$work/killed" && killed=1
wait $launcher
status=$?
[ "$killed" -eq 1 ] || fail "found no rank 1 to kill"
[ "$status" -ne 0 ] || fail "a killed rank ended the run with status 0"
grep -q "rank 1 .*signal 9" "$work/stderr" || { cat "$work/stderr"; fail "no message naming the killed rank"; }
[ ! -e "$work/killed" ] || fail "a killed run left an output"
solve_on 1 "$work/after-kill" "${progressive[@]}" --resume "$work/killed.ckpt"
same_solve "resumed after a killed rank" "$work/solve-1" "$work/after-kill"
echo "ok   rank 1 killed: status $status, the rank named, no output; its last checkpoint resumed to the straight result"

# Every report.json above fits docs/reference/report.schema.json. mpirun starts the program
# itself and the signals to rank 1 find it by its command line, so the reports are checked here
# rather than by the wrapper the other tests run solves through (tests/tools/radiosity_checked.py).
python3 "$source/tests/tools/validate_report.py" "$work"/*/report.json ||
  fail "a report.json does not fit docs/reference/report.schema.json"
echo "ok   every report.json ($(ls "$work"/*/report.json | wc -l)) fits docs/reference/report.schema.json"
