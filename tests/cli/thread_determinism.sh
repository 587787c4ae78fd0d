#!/usr/bin/env bash
# Same seed, same numbers, with 1 and 2 PoCL threads: the CSVs must be bitwise identical.
# Usage: thread_determinism.sh RADIOSITY SCENE WORKDIR
set -euo pipefail
radiosity=$1 scene=$2 work=$3
mkdir -p "$work"
for threads in 1 2; do
  POCL_MAX_PTHREAD_COUNT=$threads "$radiosity" viewfactors "$scene" --rays 200000 --seed 3 \
    --output "$work/threads-$threads.csv" 2>/dev/null
done
if ! cmp "$work/threads-1.csv" "$work/threads-2.csv"; then
  diff "$work/threads-1.csv" "$work/threads-2.csv" | head
  exit 1
fi
lines=$(wc -l < "$work/threads-1.csv")
[ "$lines" -gt 10 ] || { echo "only $lines lines"; exit 1; }
echo "identical: $lines lines"
