#!/usr/bin/env bash
# A device that cannot hold the scene: PoCL limited to 1 GiB (POCL_MEMORY_LIMIT) is asked for
# a 5.5-million-patch mesh, and for a 16384 x 16384 image of the direct camera pass (its buffers
# are reserved before the pass starts). Expect exit status 1, one line with the figures, no
# outputs.
# Usage: device_faults.sh RADIOSITY SCENE WORKDIR
set -uo pipefail
radiosity=$1 scene=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
# refused WHAT PATTERN OUTPUT ARGS...: the solve with ARGS on the limited device fails as above,
# its one line matching PATTERN.
refused() {
  local what=$1 pattern=$2 out=$3 status
  shift 3
  POCL_MEMORY_LIMIT=1 RADIOSITY_DEVICE=pocl "$radiosity" solve "$scene" --quiet --output "$out" "$@" 2>"$work/stderr"
  status=$?
  cat "$work/stderr"
  [ $status -eq 1 ] || { echo "FAIL: $what: exit status $status, expected 1"; exit 1; }
  [ "$(wc -l < "$work/stderr")" -eq 1 ] || { echo "FAIL: $what: expected one line"; exit 1; }
  grep -q "$pattern" "$work/stderr" || { echo "FAIL: $what: no figures in the message"; exit 1; }
  [ ! -e "$out" ] || { echo "FAIL: $what: output left behind: $(ls -A "$out")"; exit 1; }
}
refused "the mesh" "MiB" "$work/out" --patch-size 0.0012 --max-shots 1
refused "the camera pass" "camera pass.*MiB" "$work/image" --patch-size 0.1 --render direct --width 16384 --height 16384
echo "ok"
