#pragma once
// glTF 2.0 (.gltf with embedded or external buffers, and .glb) into a Scene.

#include <string>

#include "scene/scene.h"

namespace rad {

// Loads the file's default scene (or its first, or every root node when it has none).
// Throws FileError naming the file and the problem for anything malformed: broken JSON or
// binary chunks, missing or short buffers, accessors or indices out of range, non-finite
// positions or transforms, node cycles, unsupported required extensions, no triangles.
// Points and lines are skipped, degenerate triangles dropped; both are counted in
// Scene::warnings.
Scene loadGltf(const std::string& path);

// The same for a file already read: `path` names it in messages, and its directory is where
// external buffers are looked for.
Scene loadGltfFromMemory(const std::string& path, const std::string& bytes);

}  // namespace rad
