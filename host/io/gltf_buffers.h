#pragma once
// Building a binary glTF with tinygltf: one buffer that every view appends to, accessors over
// the views, images as PNG in the buffer, a root node placed at the scene's origin, and the
// file written whole. Shared by the baked glTF writers (lit.glb, lightmapped.glb).

#include <cstddef>
#include <string>
#include <vector>

#include <glm/ext/vector_double3.hpp>

#include <tiny_gltf.h>

#include "scene/scene.h"

namespace rad {

// A model of one buffer and one scene whose node 0, the root, is translated to `origin` (where
// the surfaces' coordinates are relative to: Scene::origin); the surfaces' nodes go under it.
tinygltf::Model startGlb(const std::string& generator, const glm::dvec3& origin);

// Adds `mesh` and a node named `name` holding it under the root (node 0).
void addSurfaceNode(tinygltf::Model& model, tinygltf::Mesh mesh, const std::string& name);

// Encodes `model` as binary glTF and writes it to `path` whole or not at all.
void writeGlb(const std::string& path, tinygltf::Model& model);

// Appends raw bytes to buffer 0 (4-byte aligned) and returns a view over them.
int addView(tinygltf::Model& model, const void* data, std::size_t bytes, int target);

int addAccessor(tinygltf::Model& model, int view, int componentType, int type, std::size_t count,
                std::vector<double> min = {}, std::vector<double> max = {});

// The image as a PNG in the file's buffer; its index among the file's images.
int addPngImage(tinygltf::Model& model, const TextureImage& image);

}  // namespace rad
