#pragma once
// Building a binary glTF with tinygltf: one buffer that every view appends to, accessors over
// the views, images as PNG in the buffer. Shared by the baked glTF writers (lit.glb,
// lightmapped.glb).

#include <cstddef>
#include <vector>

#include <tiny_gltf.h>

#include "scene/scene.h"

namespace rad {

// Appends raw bytes to buffer 0 (4-byte aligned) and returns a view over them.
int addView(tinygltf::Model& model, const void* data, std::size_t bytes, int target);

int addAccessor(tinygltf::Model& model, int view, int componentType, int type, std::size_t count,
                std::vector<double> min = {}, std::vector<double> max = {});

// The image as a PNG in the file's buffer; its index among the file's images.
int addPngImage(tinygltf::Model& model, const TextureImage& image);

}  // namespace rad
