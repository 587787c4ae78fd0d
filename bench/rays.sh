#!/usr/bin/env bash
# Rays per second of the shoot kernel on the Cornell box at about 16k patches, with 1 and 2
# PoCL threads: tracing the scene's own 32 faces, and tracing the 16k patches as faces.
# Usage: bench/rays.sh [build-dir] [extra bench_rays options]
set -euo pipefail
build=${1:-build}
shift || true
bench="$build/bench/bench_rays"
[ -x "$bench" ] || { echo "build first: scripts/setup.sh" >&2; exit 1; }
header=1
for tessellate in "" "--tessellate"; do
  for threads in 1 2; do
    out=$(POCL_MAX_PTHREAD_COUNT=$threads "$bench" $tessellate "$@")
    if [ $header -eq 1 ]; then echo "$out" | head -1; header=0; fi
    echo "$out" | tail -1
  done
done
