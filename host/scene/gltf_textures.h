#pragma once
// glTF textures: the images a document holds, decoded (PNG and JPEG, by stb_image), and the
// texture references of materials (textureInfo: image, sampler, TEXCOORD set,
// KHR_texture_transform). What cannot be honoured is warned about by name and the texture is
// left out, so the material's factors alone apply.

#include <string>
#include <vector>

#include "scene/scene.h"

namespace tinygltf {
class Model;
struct Image;
struct TextureInfo;
}  // namespace tinygltf

namespace rad {

// tinygltf's image callback: decodes the bytes into 8-bit RGBA (image->image), or leaves the
// image empty with a warning when they are not a PNG or JPEG it can read, or are too large.
// `user`: a long long, the texels all of the file's images may still take (kMostImageTexels,
// scene/image_decode.h).
bool decodeGltfImage(tinygltf::Image* image, int index, std::string* err, std::string* warn, int requestedWidth,
                     int requestedHeight, const unsigned char* bytes, int size, void* user);

class GltfTextures {
public:
    GltfTextures(const tinygltf::Model& model, std::vector<std::string>& warnings)
        : model_(model), warnings_(warnings) {}

    // The scene's images, in the document's order (empty ones where decoding failed).
    std::vector<TextureImage> images() const;

    // A material's texture (`slot` names it in warnings, with `what`); absent when the file has
    // none or it cannot be honoured.
    TextureRef reference(const tinygltf::TextureInfo& info, const std::string& what, const char* slot) const;

private:
    const tinygltf::Model& model_;
    std::vector<std::string>& warnings_;
};

}  // namespace rad
