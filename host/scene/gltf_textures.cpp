#include "scene/gltf_textures.h"

#include <algorithm>
#include <cmath>

#include <tiny_gltf.h>

#include "scene/image_decode.h"

namespace rad {
namespace {

double number(const tinygltf::Value& object, const char* key, double fallback) {
    if (!object.IsObject() || !object.Has(key)) return fallback;
    const tinygltf::Value& v = object.Get(key);
    return v.IsNumber() ? v.GetNumberAsDouble() : fallback;
}

TextureRef::Wrap wrapMode(int mode) {
    switch (mode) {
        case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE:
            return TextureRef::Wrap::ClampToEdge;
        case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT:
            return TextureRef::Wrap::MirroredRepeat;
        default:
            return TextureRef::Wrap::Repeat;
    }
}

}  // namespace

bool decodeGltfImage(tinygltf::Image* image, int index, std::string*, std::string* warn, int, int,
                     const unsigned char* bytes, int size, void* user) {
    const std::string what = "image " + std::to_string(index) + (image->name.empty() ? "" : " ('" + image->name + "')");
    TextureImage decoded;
    std::string why;
    if (!decodeImage(bytes, static_cast<std::size_t>(std::max(size, 0)), static_cast<long long*>(user), decoded, why)) {
        if (warn) *warn += what + " " + why + "; textures that use it are ignored\n";
        image->image.clear();
        image->width = image->height = 0;
        return true;  // the scene stays usable with its factors
    }
    image->width = decoded.width;
    image->height = decoded.height;
    image->component = 4;
    image->bits = 8;
    image->pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
    image->image = std::move(decoded.rgba);
    return true;
}

std::vector<TextureImage> GltfTextures::images() const {
    std::vector<TextureImage> out;
    for (std::size_t i = 0; i < model_.images.size(); ++i) {
        const tinygltf::Image& source = model_.images[i];
        TextureImage image;
        image.name = source.name.empty() ? "image" + std::to_string(i) : source.name;
        if (source.width > 0 && source.height > 0 && source.component == 4 && source.bits == 8 &&
            source.image.size() == static_cast<std::size_t>(source.width) * source.height * 4) {
            image.width = source.width;
            image.height = source.height;
            image.rgba = source.image;
        }
        out.push_back(std::move(image));
    }
    return out;
}

TextureRef GltfTextures::reference(const tinygltf::TextureInfo& info, const std::string& what, const char* slot) const {
    TextureRef ref;
    const int index = info.index;
    int texCoord = info.texCoord;
    if (index < 0) return ref;
    const std::string where = what + ": " + slot;
    if (static_cast<std::size_t>(index) >= model_.textures.size()) {
        warnings_.push_back(where + " names texture " + std::to_string(index) + ", which does not exist: ignored");
        return ref;
    }
    const tinygltf::Texture& texture = model_.textures[static_cast<std::size_t>(index)];
    // EXT_texture_webp names its WebP image in the texture's extension; `source` is then a
    // fallback (PNG or JPEG) for viewers without it, or absent.
    int source = texture.source;
    const auto webp = texture.extensions.find("EXT_texture_webp");
    if (webp != texture.extensions.end() && webp->second.IsObject() && webp->second.Has("source") &&
        webp->second.Get("source").IsInt()) {
        const int named = webp->second.Get("source").GetNumberAsInt();
        // a WebP that did not decode (its decoder warned) leaves the fallback, where there is one
        const bool decoded = named >= 0 && static_cast<std::size_t>(named) < model_.images.size() &&
                             !model_.images[static_cast<std::size_t>(named)].image.empty();
        if (decoded || source < 0) source = named;
    }
    if (source < 0 || static_cast<std::size_t>(source) >= model_.images.size()) {
        warnings_.push_back(where + ": texture " + std::to_string(index) +
                            " has no image this program reads (a KTX2 extension?): ignored");
        return ref;
    }
    const tinygltf::Image& image = model_.images[static_cast<std::size_t>(source)];
    if (image.image.empty()) return ref;  // decoding failed; the decoder warned
    // KHR_texture_transform: uv' = T R S uv, and possibly another TEXCOORD set.
    const auto transform = info.extensions.find("KHR_texture_transform");
    if (transform != info.extensions.end() && transform->second.IsObject()) {
        const tinygltf::Value& t = transform->second;
        const double ox =
            t.Has("offset") && t.Get("offset").ArrayLen() == 2 ? t.Get("offset").Get(0).GetNumberAsDouble() : 0.0;
        const double oy =
            t.Has("offset") && t.Get("offset").ArrayLen() == 2 ? t.Get("offset").Get(1).GetNumberAsDouble() : 0.0;
        const double sx =
            t.Has("scale") && t.Get("scale").ArrayLen() == 2 ? t.Get("scale").Get(0).GetNumberAsDouble() : 1.0;
        const double sy =
            t.Has("scale") && t.Get("scale").ArrayLen() == 2 ? t.Get("scale").Get(1).GetNumberAsDouble() : 1.0;
        const double r = number(t, "rotation", 0.0);
        constexpr double kLargest = 1e6;  // beyond this, float texture coordinates carry no texel detail
        if (!(std::fabs(ox) <= kLargest && std::fabs(oy) <= kLargest && std::fabs(sx) <= kLargest &&
              std::fabs(sy) <= kLargest && std::fabs(r) <= kLargest)) {
            warnings_.push_back(where +
                                ": KHR_texture_transform has a value that is not a finite number within 1e6: "
                                "the texture is ignored");
            return ref;
        }
        const double c = std::cos(r), s = std::sin(r);
        // Columns of T R S (the extension's matrices are written row by row).
        ref.transform = glm::mat3(glm::vec3(static_cast<float>(c * sx), static_cast<float>(-s * sx), 0.0f),
                                  glm::vec3(static_cast<float>(s * sy), static_cast<float>(c * sy), 0.0f),
                                  glm::vec3(static_cast<float>(ox), static_cast<float>(oy), 1.0f));
        if (t.Has("texCoord") && t.Get("texCoord").IsInt()) texCoord = t.Get("texCoord").GetNumberAsInt();
    }
    if (texCoord < 0 || texCoord > 1) {
        warnings_.push_back(where + " reads TEXCOORD_" + std::to_string(texCoord) +
                            "; only TEXCOORD_0 and TEXCOORD_1 are read: the texture is ignored");
        return ref;
    }
    ref.image = source;
    ref.texCoord = texCoord;
    if (texture.sampler >= 0 && static_cast<std::size_t>(texture.sampler) < model_.samplers.size()) {
        const tinygltf::Sampler& sampler = model_.samplers[static_cast<std::size_t>(texture.sampler)];
        ref.wrapS = wrapMode(sampler.wrapS);
        ref.wrapT = wrapMode(sampler.wrapT);
        ref.nearest = sampler.magFilter == TINYGLTF_TEXTURE_FILTER_NEAREST;
    }
    return ref;
}

}  // namespace rad
