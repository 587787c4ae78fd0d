#!/usr/bin/env bash
# Installs the Debian 12 packages the build needs (only those missing), then configures and
# builds in Release mode into build/. Safe to run again; nothing is downloaded at build time.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(
  g++ cmake make pkg-config
  pocl-opencl-icd mesa-opencl-icd ocl-icd-opencl-dev opencl-c-headers opencl-clhpp-headers clinfo
  libglm-dev libtinygltf-dev nlohmann-json3-dev libstb-dev
  libopenexr-dev libcli11-dev libgtest-dev
  libeigen3-dev clang libclang-rt-14-dev
  libtinyobjloader-dev  # OBJ files (host/scene/obj_reader.cpp)
  libdraco-dev  # KHR_draco_mesh_compression (host/scene/gltf_draco.cpp)
  libmeshoptimizer-dev  # EXT_meshopt_compression (host/scene/gltf_meshopt.cpp)
  libwebp-dev  # EXT_texture_webp (host/scene/image_decode.cpp)
  libopenmpi-dev openmpi-bin
  python3-matplotlib python3-numpy
  libembree-dev  # bench/embree_compare only: the program never links Embree
  python3-jsonschema  # the tests check every report.json against docs/reference/report.schema.json
  pybind11-dev python3-pybind11 python3-dev  # the Python module (python/), built when these are found
  python3-pytest python3-scipy  # its tests (tests/python/) and its sparse matrices
  python3-venv python3-pip python3-setuptools python3-wheel git  # the test of pip install into a fresh venv
  assimp-testmodels  # other projects' models the tests read (the Draco-compressed 2CylinderEngine)
  mkdocs  # the user guide (docs/, mkdocs.yml) and its test docs_site_builds
)
# --mitsuba-llvm: also the LLVM that Mitsuba 3's fast variant runs on, for bench/mitsuba_compare
# (Mitsuba itself comes from PyPI into that bench's virtual environment; without this LLVM it
# runs Mitsuba's scalar variant). Left out by default: nothing else needs it.
for argument in "$@"; do
  case "$argument" in
    --mitsuba-llvm) packages+=(libllvm19) ;;
    *) echo "setup: unknown option $argument (known: --mitsuba-llvm)" >&2; exit 2 ;;
  esac
done
missing=()
for package in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || missing+=("$package")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo=sudo
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# The Python module is built for Debian's interpreter, whose packages the list above installs
# (another python3 may come first on PATH).
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DPython_EXECUTABLE=/usr/bin/python3 >/dev/null
cmake --build build -j"$(nproc)"
