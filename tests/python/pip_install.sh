#!/usr/bin/env bash
# The Python module as a user installs it: `pip install --no-build-isolation .` into a fresh
# virtual environment (with Debian's NumPy and SciPy through --system-site-packages, nothing
# downloaded: --no-index), from a copy of the repository's files, then a ten-line script run
# from outside the repository computes the Cornell box's view factors and heat exchange and must
# print exactly what the program prints. The module is taken from this build
# (RADIOSITY_BUILD_DIR) rather than compiled a second time.
# Usage: pip_install.sh PYTHON RADIOSITY SOURCE_DIR BUILD_DIR WORKDIR
set -euo pipefail
python=$1 radiosity=$2 source=$3 build=$4 work=$5
rm -rf "$work" && mkdir -p "$work/src"
# The repository's own files (as a fresh clone has them), not the build.
(cd "$source" && git ls-files -z --cached --others --exclude-standard |
  while IFS= read -r -d '' f; do [ -e "$f" ] && cp --parents -- "$f" "$work/src"; done; true)
"$python" -m venv --system-site-packages "$work/venv"
RADIOSITY_BUILD_DIR=$build "$work/venv/bin/pip" install -q --no-index --no-build-isolation "$work/src" \
  >"$work/pip.log" 2>&1 || { cat "$work/pip.log"; echo "FAIL: pip install"; exit 1; }
cat > "$work/study.py" <<PY
import radiosity
scene = "$source/scenes/cornell-box.gltf"
vf = radiosity.view_factors(scene, rays=100_000)
open("vf.csv", "w").write(vf.to_csv())
heat = radiosity.exchange(scene, properties={"light": {"emissivity": 0.9, "temperature": 600}},
                          default_emissivity=0.8, default_temperature=300, rays=100_000)
open("heat.csv", "w").write(heat.to_csv())
assert vf.matrix.shape == (8, 8) and abs(heat.net_heat.sum()) > 0
print(radiosity.__file__)
PY
(cd "$work" && PYTHONPATH= "$work/venv/bin/python" -W ignore study.py > where.txt)
case $(cat "$work/where.txt") in
  "$work/venv/"*) ;;
  *) echo "FAIL: radiosity was imported from $(cat "$work/where.txt"), not the environment"; exit 1 ;;
esac
printf 'surface,emissivity,temperature\nlight,0.9,600\n' > "$work/properties.csv"
"$radiosity" viewfactors "$source/scenes/cornell-box.gltf" --rays 100000 > "$work/vf-program.csv" 2>/dev/null
"$radiosity" exchange "$source/scenes/cornell-box.gltf" --properties "$work/properties.csv" --default-emissivity 0.8 \
  --default-temperature 300 --rays 100000 > "$work/heat-program.csv" 2>/dev/null
cmp "$work/vf.csv" "$work/vf-program.csv" || { echo "FAIL: view factors differ from the program's"; exit 1; }
cmp "$work/heat.csv" "$work/heat-program.csv" || { echo "FAIL: heat exchange differs from the program's"; exit 1; }
echo "ok   pip install into a fresh environment; the script's view factors ($(($(wc -l < "$work/vf.csv") - 1)) rows) and heat exchange are the program's, byte for byte"
