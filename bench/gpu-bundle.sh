#!/usr/bin/env bash
# Packs the built binaries with the shared libraries they need that a bare GPU machine may
# lack (the OpenCL ICD loader, tinygltf, OpenEXR, stb, libstdc++, ...) into .gpu/, plus an ICD file that
# points the loader at NVIDIA's OpenCL driver. On the GPU machine, from the repository root:
#   export LD_LIBRARY_PATH=$PWD/.gpu/lib:/usr/local/nvidia/lib64 OCL_ICD_VENDORS=$PWD/.gpu/icd
#   .gpu/radiosity devices
# Usage: bench/gpu-bundle.sh [build-dir]
set -euo pipefail
build=${1:-build}
rm -rf .gpu && mkdir -p .gpu/lib .gpu/icd
cp "$build/radiosity" "$build/tests/device_tests" "$build/bench/bench_rays" "$build/bench/bench_solve" .gpu/
# Every shared library the binaries load, except the C library's own (the GPU machine's glibc
# is newer, and mixing them breaks).
for binary in .gpu/radiosity .gpu/device_tests .gpu/bench_rays .gpu/bench_solve; do
  ldd "$binary" | awk '/=> \//{print $3}'
done | sort -u | grep -vE '/(libc|libm|libpthread|libdl|librt|ld-linux[^/]*)\.so' | while read -r lib; do
  cp -L "$lib" .gpu/lib/
done
echo libnvidia-opencl.so.1 > .gpu/icd/nvidia.icd
grep -qx "/.gpu/" .git/info/exclude 2>/dev/null || { mkdir -p .git/info; echo "/.gpu/" >> .git/info/exclude; }
du -sh .gpu
