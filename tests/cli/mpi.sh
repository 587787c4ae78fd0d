#!/usr/bin/env bash
# The same view factors on 1, 2 and 3 MPI ranks (3 oversubscribed on a 2-core machine: a check
# of correctness, not speed), bitwise; and a bad scene ending every rank with one status and no
# output. Skips (77) without mpirun or when radiosity was built without MPI.
# Usage: mpi.sh RADIOSITY SOURCE_DIR WORKDIR
set -uo pipefail
radiosity=$1 source=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
command -v mpirun >/dev/null || { echo "no mpirun: skipped"; exit 77; }
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1  # CI runs as root
fail() { echo "FAIL: $*"; exit 1; }
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
