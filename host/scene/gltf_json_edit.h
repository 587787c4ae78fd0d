#pragma once
// Edits a glTF file's JSON before tinygltf parses it, for the extensions whose files tinygltf
// would otherwise refuse (scene/gltf_draco.cpp, scene/gltf_meshopt.cpp).

#include <functional>
#include <string>

#include <nlohmann/json_fwd.hpp>

namespace rad {

// The file's bytes with its JSON changed by `edit`, which returns whether it changed anything:
// a .gltf's text, or a .glb with its JSON chunk rewritten and its binary chunk kept. Bytes whose
// JSON does not parse as an object are returned as they are, for the parser to report.
std::string editGltfJson(const std::string& bytes, bool binary, const std::function<bool(nlohmann::json&)>& edit);

}  // namespace rad
