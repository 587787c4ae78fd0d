#!/usr/bin/env bash
# radiosity pathtrace from the command line: it writes the EXR it is asked for (creating its
# directory), the same seed gives the same bytes, and bad requests get exit status 2 with no file.
# Usage: pathtrace.sh RADIOSITY SOURCE_DIR WORKDIR
set -uo pipefail
radiosity=$1 source=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }
cornell="$source/scenes/cornell-box.gltf"

"$radiosity" pathtrace "$cornell" --output "$work/a/pt.exr" --width 24 --height 16 --samples 4 2>"$work/log" \
  || fail "pathtrace: $(cat "$work/log")"
[ -s "$work/a/pt.exr" ] || fail "no EXR written"
grep -q "wrote $work/a/pt.exr" "$work/log" || fail "no summary line: $(cat "$work/log")"
"$radiosity" pathtrace "$cornell" --output "$work/b.exr" --width 24 --height 16 --samples 4 2>/dev/null || fail "second run"
cmp -s "$work/a/pt.exr" "$work/b.exr" || fail "the same seed gave another image"
echo "ok: writes the EXR; same seed, same bytes"

expect_usage_error() {
  local what=$1 words=$2
  shift 2
  "$radiosity" pathtrace "$@" 2>"$work/log"
  local status=$?
  [ $status -eq 2 ] || fail "$what: exit status $status, expected 2"
  grep -q "$words" "$work/log" || fail "$what: message lacks '$words': $(cat "$work/log")"
}
expect_usage_error "unknown camera" "no camera named" "$cornell" --camera nope --output "$work/c.exr"
expect_usage_error "no emitter" "no KHR_lights_punctual light, and neither --sky nor --environment" "$source/tests/data/gltf/double-sided.gltf" --output "$work/d.exr"
expect_usage_error "output is a directory" "is a directory" "$cornell" --output "$work/a"
expect_usage_error "zero samples" "samples" "$cornell" --samples 0 --output "$work/e.exr"
[ ! -e "$work/c.exr" ] && [ ! -e "$work/d.exr" ] && [ ! -e "$work/e.exr" ] || fail "a refused run left a file"
echo "ok: refusals"
