#!/usr/bin/env bash
# OBJ (with MTL), STL and PLY files from another project's tests, as Debian's assimp-testmodels
# ships them: each gives view factors (and shares to space) byte for byte the same as the same
# geometry converted to glTF by tests/tools/mesh_to_gltf.py, a converter that shares no code
# with the program's readers. Then that project's broken and unusual files: each refused with
# exit status 2, a message naming the file and the problem, and nothing written.
# Usage: other_projects_meshes.sh RADIOSITY SOURCE_DIR WORKDIR
set -euo pipefail
radiosity=$1 source=$2 work=$3
models=/usr/share/assimp/models
[ -d "$models" ] || { echo "FAIL: $models is missing: install assimp-testmodels (scripts/setup.sh does)"; exit 1; }
rm -rf "$work" && mkdir -p "$work"
compare() {  # name, then the files read together
  local name=$1; shift
  local files=() f
  for f in "$@"; do files+=("$models/$f"); done
  python3 "$source/tests/tools/mesh_to_gltf.py" "$work/$name.gltf" "${files[@]}"
  "$radiosity" viewfactors "${files[@]}" --rays 20000 --output "$work/$name-files.csv" \
    --to-space "$work/$name-files-space.csv" 2>"$work/$name-files.log" || { cat "$work/$name-files.log"; exit 1; }
  "$radiosity" viewfactors "$work/$name.gltf" --rays 20000 --output "$work/$name-gltf.csv" \
    --to-space "$work/$name-gltf-space.csv" 2>"$work/$name-gltf.log" || { cat "$work/$name-gltf.log"; exit 1; }
  local rows=$(($(wc -l < "$work/$name-files.csv") - 1))
  [ "$rows" -gt 0 ] || { echo "FAIL $name: no view factors to compare"; exit 1; }
  cmp "$work/$name-files.csv" "$work/$name-gltf.csv" || { echo "FAIL $name: view factors differ from the glTF's"; exit 1; }
  cmp "$work/$name-files-space.csv" "$work/$name-gltf-space.csv" || { echo "FAIL $name: shares to space differ"; exit 1; }
  echo "ok   $name ($*): $rows view factors, the same bytes as from glTF"
}
compare spider-obj OBJ/spider.obj                    # 19 groups, MTL with textures the reader names
compare regr01-obj OBJ/regr01.obj                    # 55 groups, quads
compare stl-and-ply STL/Spider_ascii.stl STL/sphereWithHole.stl PLY/Wuson.ply PLY/cube_binary.ply
compare binary-stl-and-ascii-ply STL/Spider_binary.stl PLY/cube.ply
# Blender 2.4x wrote a comment into Wuson.ply's header without the word 'comment': passed over,
# and said; a misspelt keyword is still refused.
grep -q "Wuson.ply: the header line 'Created by Blender3D 247" "$work/stl-and-ply-files.log" ||
  { echo "FAIL: no warning for Wuson.ply's header line"; cat "$work/stl-and-ply-files.log"; exit 1; }
printf 'ply\nformat ascii 1.0\nelemnt vertex 3\nend_header\n' > "$work/misspelt.ply"
status=0
"$radiosity" viewfactors "$work/misspelt.ply" 2>"$work/stderr" >/dev/null || status=$?
[ "$status" -eq 2 ] && grep -q "misspelt.ply: unknown header line beginning 'elemnt'" "$work/stderr" ||
  { echo "FAIL: a misspelt PLY keyword: status $status"; cat "$work/stderr"; exit 1; }
echo "ok   a header line that is no keyword is passed over with a warning; a misspelt keyword is refused"

for case in "PLY/issue623.ply:vertex_indices" "PLY/points.ply:has no triangles" \
            "PLY/pond.0.ply:normal that is not finite" "OBJ/point_cloud.obj:has no triangles" \
            "OBJ/testline.obj:has no triangles" "OBJ/box_UTF16BE.obj:UTF-16" \
            "STL/formatDetection:none of .gltf, .glb, .obj, .stl and .ply"; do
  file=${case%%:*} problem=${case#*:}
  status=0
  "$radiosity" viewfactors "$models/$file" --output "$work/refused.csv" 2>"$work/stderr" || status=$?
  [ "$status" -eq 2 ] || { echo "FAIL $file: exit status $status, expected 2"; cat "$work/stderr"; exit 1; }
  grep -qF "$models/$file" "$work/stderr" && grep -qF "$problem" "$work/stderr" ||
    { echo "FAIL $file: the message does not name the file and '$problem'"; cat "$work/stderr"; exit 1; }
  [ ! -e "$work/refused.csv" ] || { echo "FAIL $file: left an output file"; exit 1; }
  echo "ok   $file refused: $(head -c 200 "$work/stderr")"
done
