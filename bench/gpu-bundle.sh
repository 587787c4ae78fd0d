#!/usr/bin/env bash
# Packs the built binaries with the shared libraries they need that a bare GPU machine may
# lack (the OpenCL ICD loader, tinygltf, stb, libstdc++) into .gpu/, plus an ICD file that
# points the loader at NVIDIA's OpenCL driver. On the GPU machine, from the repository root:
#   export LD_LIBRARY_PATH=$PWD/.gpu/lib:/usr/local/nvidia/lib64 OCL_ICD_VENDORS=$PWD/.gpu/icd
#   .gpu/radiosity devices
# Usage: bench/gpu-bundle.sh [build-dir]
set -euo pipefail
build=${1:-build}
rm -rf .gpu && mkdir -p .gpu/lib .gpu/icd
cp "$build/radiosity" "$build/tests/device_tests" "$build/bench/bench_rays" .gpu/
for lib in libOpenCL.so.1 libstb.so.0 libtinygltf.so.2d libstdc++.so.6 libgcc_s.so.1; do
  cp "/lib/x86_64-linux-gnu/$lib" .gpu/lib/
done
echo libnvidia-opencl.so.1 > .gpu/icd/nvidia.icd
grep -qx "/.gpu/" .git/info/exclude 2>/dev/null || { mkdir -p .git/info; echo "/.gpu/" >> .git/info/exclude; }
du -sh .gpu
