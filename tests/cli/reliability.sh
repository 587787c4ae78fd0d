#!/usr/bin/env bash
# Warnings where a result is unreliable (host/formfactor/sampling_checks.h before the work,
# host/solver/ray_hit_checks.h after a progressive solve): each appears on stderr and in
# report.json with its remedy when its cause is there, and a well-sampled solve has none.
# Usage: reliability.sh RADIOSITY SOURCE_DIR WORKDIR
set -uo pipefail
radiosity=$1 source=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }
cornell="$source/scenes/cornell-box.gltf"

solve() {  # solve NAME ARGS...: a small solve into $work/NAME, stderr in $work/NAME.log
  local name=$1
  shift
  "$radiosity" solve "$cornell" --patch-size 0.15 --width 8 --height 8 --quiet --output "$work/$name" "$@" \
    2>"$work/$name.log" || fail "$name: $(cat "$work/$name.log")"
}
expect() {  # expect NAME WORDS: in the report's warnings and on stderr
  grep -q "warning: .*$2" "$work/$1.log" || fail "$1: no warning with '$2' on stderr: $(cat "$work/$1.log")"
  python3 -c "import json,sys; w=json.load(open(sys.argv[1]))['warnings']; sys.exit(not any(sys.argv[2] in x for x in w))" \
    "$work/$1/report.json" "$2" || fail "$1: no warning with '$2' in report.json"
}

solve clean --rays 4e6
python3 -c "import json,sys; w=json.load(open(sys.argv[1]))['warnings']; sys.exit(len(w) != 0)" "$work/clean/report.json" \
  || fail "a well-sampled solve warned: $(cat "$work/clean.log")"
echo "ok: no warning for a well-sampled solve"

solve sparse --rays 5e3 --min-rays 1
expect sparse "patch values carry about"
expect sparse "got no ray hit"
expect sparse "use --rays"
# The report states the noise the solve expects, and it is what warned.
python3 -c "import json,sys; n=json.load(open(sys.argv[1]))['solve']['expected_noise']; sys.exit(not n > 0.1)" \
  "$work/sparse/report.json" || fail "sparse: expected_noise not above 0.1"
python3 -c "import json,sys; n=json.load(open(sys.argv[1]))['solve']['expected_noise']; sys.exit(not 0 < n < 0.1)" \
  "$work/clean/report.json" || fail "clean: expected_noise not between 0 and 0.1"
echo "ok: too few ray hits"

# Split patches: the hits are counted per element; a quarter of the rays that are enough for
# these patches leaves about 8 per element four levels finer.
solve split --rays 1e6 --element-size 0.01
expect split "element values carry about"
expect split "use --rays"
echo "ok: too few ray hits per element"

solve pixels --method hemicube --hemicube-res 8 --solver gauss-seidel
expect pixels "hemicube pixel"
expect pixels "use --hemicube-res"
expect pixels "nearer than their own size"
echo "ok: hemicube pixels larger than the smallest patches; near field"

solve rows --method shoot --solver jacobi --rays-per-patch 64
expect rows "use --rays-per-patch"
echo "ok: too few rays per patch"

"$radiosity" viewfactors "$source/scenes/perpendicular-squares.gltf" --method gather --patch-size 0.25 \
  >/dev/null 2>"$work/vf.log" || fail "viewfactors: $(cat "$work/vf.log")"
grep -q "warning: gather: .*nearer than their own size" "$work/vf.log" || fail "viewfactors: no near-field warning"
echo "ok: viewfactors warns too"

# Surface view factors are read entry by entry: a receiver that expects about 48 rays (14 %
# noise) is warned about with the --rays for 100; a well-sampled one is not.
"$radiosity" viewfactors "$source/bench/scenes/small-receiver-0.03.gltf" --rays 1e6 >/dev/null 2>"$work/vf.log" \
  || fail "viewfactors: $(cat "$work/vf.log")"
grep -q "warning: shoot: .*fewer than 100 rays.*use --rays 2.09e+06" "$work/vf.log" || fail "small receiver: $(cat "$work/vf.log")"
"$radiosity" viewfactors "$source/bench/scenes/small-receiver-0.03.gltf" --rays 4e6 >/dev/null 2>"$work/vf.log" \
  || fail "viewfactors: $(cat "$work/vf.log")"
! grep -q "warning" "$work/vf.log" || fail "4e6 rays, 190 on the receiver, warned: $(cat "$work/vf.log")"
echo "ok: surface view factors warn below 100 rays per receiver"
