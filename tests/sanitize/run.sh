#!/usr/bin/env bash
# Builds the project with clang, AddressSanitizer and UndefinedBehaviorSanitizer into WORKDIR,
# then: runs the host unit tests under the sanitizers; runs the command-line bad-input checks
# with the sanitized program; runs the glTF fuzzer over its whole corpus (the test data, the
# bundled scenes, and every input a fuzzing run ever found in tests/fuzz/found); and fuzzes
# for a bounded number of runs from a fixed seed. Skips (77) where clang is missing.
# Usage: tests/sanitize/run.sh SOURCE_DIR WORKDIR [FUZZ_RUNS]
set -euo pipefail
source=$1 work=$2 runs=${3:-30000}
command -v clang++ >/dev/null || { echo "clang++ not installed: skipped"; exit 77; }
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1

# -O1 with line tables: what the sanitizers' authors recommend for readable reports, and a quarter
# faster to compile than -O2 -g (this build is the longest part of CI); -O0 compiled three times
# faster but ran the host tests 15 times slower.
cmake -S "$source" -B "$work" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -gline-tables-only -DNDEBUG" -DCMAKE_CXX_COMPILER=clang++ \
  -DRADIOSITY_SANITIZE=ON -DRADIOSITY_FUZZ=ON >"$work.configure.log" 2>&1 || { cat "$work.configure.log"; exit 1; }
cmake --build "$work" -j"$(nproc)" --target host_tests gltf_fuzzer radiosity

echo "== host unit tests under ASan + UBSan"
"$work/tests/host_tests" --gtest_brief=1

echo "== bad input through the sanitized program"
# PoCL is not built with the sanitizers; its own allocations are not ours to report.
ASAN_OPTIONS=detect_leaks=0:abort_on_error=1 bash "$source/tests/cli/bad_input.sh" "$work/radiosity" \
  "$source/tests/data/bad" "$work/cli-bad-input" >"$work/bad-input.log" 2>&1 ||
  { cat "$work/bad-input.log"; exit 1; }
grep -v '^ok' "$work/bad-input.log" || true

echo "== fuzzer over the corpus"
corpus="$work/fuzz-corpus"
rm -rf "$corpus" && mkdir -p "$corpus"
for f in "$source"/tests/data/gltf/*.gl* "$source"/tests/data/bad/*.gl* "$source"/scenes/*.gltf \
         "$source"/tests/data/solve/*.gltf "$source"/tests/fuzz/found/*; do
  [ -f "$f" ] && cp "$f" "$corpus/$(echo "${f#$source/}" | tr '/' '_')"
done
"$work/gltf_fuzzer" -runs=0 "$corpus"

echo "== bounded fuzzing: $runs runs from seed 1"
rm -rf "$work/fuzz-new" && mkdir -p "$work/fuzz-new"
"$work/gltf_fuzzer" -seed=1 -runs="$runs" -max_len=8192 -rss_limit_mb=2048 \
  -artifact_prefix="$work/fuzz-artifact-" "$work/fuzz-new" "$corpus"
