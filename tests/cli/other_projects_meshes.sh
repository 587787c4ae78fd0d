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
# and said. A keyword misspelt or in capitals, a property after such a line, and values the header
# does not describe are refused: each would misread the data.
grep -q "Wuson.ply: the header line 'Created by Blender3D 247" "$work/stl-and-ply-files.log" ||
  { echo "FAIL: no warning for Wuson.ply's header line"; cat "$work/stl-and-ply-files.log"; exit 1; }
square='element vertex 4\nproperty float x\nproperty float y\nproperty float z\nelement face 2\nproperty list uchar int vertex_indices\n'
data='0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n'
for case in "misspelt:elemnt vertex 3\n:unknown header line beginning 'elemnt'" \
            "capitals:${square}Element extra 1\nproperty float q\n:unknown header line beginning 'Element'" \
            "prose-then-property:${square}Extra values follow\ncomment x\nproperty float q\n:is not PLY, with no element between" \
            "undescribed-values:${square}:values after its last element that the header does not describe"; do
  IFS=: read -r name header problem <<<"$case"
  extra=""; [ "$name" = undescribed-values ] && extra='7\n'
  printf "ply\nformat ascii 1.0\n${header}end_header\n${data}${extra}" > "$work/$name.ply"
  status=0
  "$radiosity" viewfactors "$work/$name.ply" 2>"$work/stderr" >/dev/null || status=$?
  [ "$status" -eq 2 ] && grep -qF "$name.ply: " "$work/stderr" && grep -qF "$problem" "$work/stderr" ||
    { echo "FAIL: PLY $name: status $status"; cat "$work/stderr"; exit 1; }
done
echo "ok   a PLY header line that is no keyword is passed over with a warning; misspelt or capital keywords, a property after such a line and undescribed values are refused"

for case in "PLY/issue623.ply:vertex_indices" "PLY/points.ply:has no triangles" \
            "PLY/pond.0.ply:vertex 714 (counting from 0) is not a finite point" "OBJ/point_cloud.obj:has no triangles" \
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
