#!/usr/bin/env bash
# Same seed, same numbers, with 1 and 2 PoCL threads (--threads): the CSVs must be bitwise
# identical. --threads reaches PoCL (the devices command shows its compute units), and wins over
# POCL_MAX_PTHREAD_COUNT; --version answers.
# Usage: thread_determinism.sh RADIOSITY SCENE WORKDIR
set -euo pipefail
radiosity=$1 scene=$2 work=$3
mkdir -p "$work"
for threads in 1 2; do
  POCL_MAX_PTHREAD_COUNT=3 "$radiosity" viewfactors "$scene" --rays 200000 --seed 3 --threads $threads \
    --output "$work/threads-$threads.csv" 2>/dev/null
  units=$(POCL_MAX_PTHREAD_COUNT=3 "$radiosity" devices --threads $threads | grep -i "pthread" | grep -o "[0-9]* compute units")
  [ "$units" = "$threads compute units" ] || { echo "FAIL: --threads $threads gave PoCL '$units'"; exit 1; }
done
if ! cmp "$work/threads-1.csv" "$work/threads-2.csv"; then
  diff "$work/threads-1.csv" "$work/threads-2.csv" | head
  exit 1
fi
lines=$(wc -l < "$work/threads-1.csv")
[ "$lines" -gt 10 ] || { echo "only $lines lines"; exit 1; }
echo "identical: $lines lines; PoCL showed 1 and 2 compute units"
"$radiosity" --version | grep -Eq "^radiosity [0-9]+\.[0-9]+\.[0-9]+$" || { echo "FAIL: --version"; exit 1; }
echo "ok   --version: $("$radiosity" --version)"
