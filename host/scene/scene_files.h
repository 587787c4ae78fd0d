#pragma once
// The scene a command reads: one glTF file (.gltf, .glb), or one or more mesh files (OBJ, STL,
// PLY; scene/mesh_files.h) read together into one scene.

#include <string>
#include <vector>

#include "scene/scene.h"

namespace rad {

// Metres per unit for the names --unit takes: m, cm, mm, in, ft. Throws InputError for another.
double metresPerUnit(const std::string& unit);

// Throws FileError for a glTF file given beside others, or a unit other than metres with glTF
// (which is in metres by definition); otherwise what loadGltf or loadMeshFiles throws.
Scene loadScene(const std::vector<std::string>& paths, const std::string& unit = "m");

}  // namespace rad
