#!/usr/bin/env bash
# The recorded results (tests/regression/same_results.py) with the kernels built against PoCL's
# plain SSE2 kernel library for a generic x86-64 CPU, instead of the variant PoCL picks for this
# CPU (AVX2 or AVX-512). The variants implement conversions and other builtins with different
# instructions, so any undefined behaviour in a kernel (a plain cast of a float out of an
# integer's range gave 2^32 - 1 under AVX-512 and 0 under AVX2) shows up as different bits; the
# recorded fingerprints were once right only on machines whose PoCL picked AVX2.
# Usage: kernel_library_variants.sh RADIOSITY SOURCE_DIR WORKDIR. Exit 77 (skipped) where PoCL
# has no x86-64 SSE2 kernel library (another architecture, or PoCL installed elsewhere).
set -euo pipefail
radiosity=$1 source=$2 work=$3
library=$(ls /usr/share/pocl/kernel-x86_64-*-sse2.bc /usr/lib/*/pocl/kernel-x86_64-*-sse2.bc \
  /usr/local/share/pocl/kernel-x86_64-*-sse2.bc 2>/dev/null | head -1 || true)
if [[ -z "$library" ]]; then
    echo "skipped: no PoCL SSE2 kernel library for x86-64 here"
    exit 77
fi
pocl_device() { "$radiosity" devices | grep -m1 "Portable Computing Language" || true; }
native=$(pocl_device)
[[ -n "$native" ]] || { echo "skipped: no PoCL device"; exit 77; }
# POCL_KERNELLIB_NAME picks the library; POCL_LLVM_CPU_NAME the CPU the kernels are compiled
# for, which is also what PoCL keys its kernel cache by: without it the runs below could reuse
# the binaries built for this CPU. A cache of its own makes sure they do not.
rm -rf "$work" && mkdir -p "$work"
export POCL_KERNELLIB_NAME=sse2 POCL_LLVM_CPU_NAME=x86-64 POCL_CACHE_DIR="$work/pocl-cache"
generic=$(pocl_device)
# The device must really be another build (PoCL names it after the CPU it compiles for, e.g.
# athlon64), or this checks nothing new.
if [[ "$generic" == "$native" ]]; then
    echo "PoCL did not take POCL_KERNELLIB_NAME=sse2: $generic"
    exit 1
fi
echo "generic build: $generic"
python3 "$source/tests/regression/same_results.py" "$radiosity" "$source" "$work/runs"
