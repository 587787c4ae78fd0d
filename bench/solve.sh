#!/usr/bin/env bash
# A whole progressive solve of the Cornell box at about 16k patches to tolerance 1e-3, with
# 1 and 2 PoCL threads, three runs each (take the median; the machine is shared).
# Usage: bench/solve.sh [build-dir] [extra bench_solve options]
set -euo pipefail
build=${1:-build}
shift || true
bench="$build/bench/bench_solve"
[ -x "$bench" ] || { echo "build first: scripts/setup.sh" >&2; exit 1; }
header=1
for threads in 1 2; do
  for run in 1 2 3; do
    out=$(POCL_MAX_PTHREAD_COUNT=$threads "$bench" --rays 16e6 "$@")
    if [ $header -eq 1 ]; then echo "$out" | head -1; header=0; fi
    echo "$out" | tail -1
  done
done
