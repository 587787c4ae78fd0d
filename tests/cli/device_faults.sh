#!/usr/bin/env bash
# A device that cannot hold the scene: PoCL limited to 1 GiB (POCL_MEMORY_LIMIT) is asked for
# a 5.5-million-patch mesh, and for a 16384 x 16384 image of the direct camera pass (its buffers
# are reserved before the pass starts). Expect exit status 1, one line with the figures, no
# outputs.
# Usage: device_faults.sh RADIOSITY SCENE WORKDIR
set -uo pipefail
radiosity=$1 scene=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
POCL_MEMORY_LIMIT=1 RADIOSITY_DEVICE=pocl "$radiosity" solve "$scene" --patch-size 0.0012 --max-shots 1 --quiet \
  --output "$work/out" 2>"$work/stderr"
status=$?
cat "$work/stderr"
[ $status -eq 1 ] || { echo "FAIL: exit status $status, expected 1"; exit 1; }
[ "$(wc -l < "$work/stderr")" -eq 1 ] || { echo "FAIL: expected one line"; exit 1; }
grep -q "MiB" "$work/stderr" || { echo "FAIL: no figures in the message"; exit 1; }
[ ! -e "$work/out" ] || { echo "FAIL: output left behind: $(ls -A "$work/out")"; exit 1; }
POCL_MEMORY_LIMIT=1 RADIOSITY_DEVICE=pocl "$radiosity" solve "$scene" --patch-size 0.1 --render direct --width 16384 \
  --height 16384 --quiet --output "$work/image" 2>"$work/stderr"
status=$?
cat "$work/stderr"
[ $status -eq 1 ] || { echo "FAIL: camera pass: exit status $status, expected 1"; exit 1; }
[ "$(wc -l < "$work/stderr")" -eq 1 ] || { echo "FAIL: camera pass: expected one line"; exit 1; }
grep -q "camera pass.*MiB" "$work/stderr" || { echo "FAIL: camera pass: no figures in the message"; exit 1; }
[ ! -e "$work/image" ] || { echo "FAIL: camera pass: output left behind: $(ls -A "$work/image")"; exit 1; }
echo "ok"
