#include "scene/image_decode.h"

#include <algorithm>
#include <climits>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include <stb_image.h>
#include <webp/decode.h>

namespace rad {

bool decodeImage(const unsigned char* bytes, std::size_t size, long long* budget, TextureImage& image, std::string& why) {
    image.width = image.height = 0;
    image.rgba.clear();
    // PNG or JPEG only: stb_image reads more formats (HDR, among others, tone-mapped), which glTF
    // does not allow and which would be misread as sRGB.
    const bool png = size >= 8 && bytes[0] == 0x89 && bytes[1] == 'P' && bytes[2] == 'N' && bytes[3] == 'G';
    const bool jpeg = size >= 3 && bytes[0] == 0xFF && bytes[1] == 0xD8 && bytes[2] == 0xFF;
    const bool webp = size >= 12 && std::memcmp(bytes, "RIFF", 4) == 0 && std::memcmp(bytes + 8, "WEBP", 4) == 0;
    const int length = static_cast<int>(std::min<std::size_t>(size, INT_MAX));
    int width = 0, height = 0, channels = 0;
    const bool known = webp ? WebPGetInfo(bytes, size, &width, &height) != 0
                            : (png || jpeg) && stbi_info_from_memory(bytes, length, &width, &height, &channels) != 0;
    if (!known) {
        why = "is not a PNG, JPEG or WebP image this program can read";
        return false;
    }
    if (width <= 0 || height <= 0 || static_cast<long long>(width) * height > kMostImageTexels) {
        why = "is " + std::to_string(width) + " x " + std::to_string(height) + " texels, more than the " +
              std::to_string(kMostImageTexels) + " read";
        return false;
    }
    if (budget) {
        if (static_cast<long long>(width) * height > *budget) {
            why = "would take the file's images past " + std::to_string(kMostImageTexels) + " texels in all";
            return false;
        }
        *budget -= static_cast<long long>(width) * height;
    }
    if (webp) {  // libwebp (EXT_texture_webp)
        uint8_t* texels = WebPDecodeRGBA(bytes, size, &width, &height);
        if (!texels) {
            why = "cannot be decoded as WebP";
            return false;
        }
        image.rgba.assign(texels, texels + static_cast<std::size_t>(width) * height * 4);
        WebPFree(texels);
    } else {
        unsigned char* texels = stbi_load_from_memory(bytes, length, &width, &height, &channels, 4);
        if (!texels) {
            why = std::string("cannot be decoded (") + stbi_failure_reason() + ")";
            return false;
        }
        image.rgba.assign(texels, texels + static_cast<std::size_t>(width) * height * 4);
        stbi_image_free(texels);
    }
    image.width = width;
    image.height = height;
    return true;
}

std::string imagePath(const std::string& folder, const std::string& name) {
    std::string slashed = name;
    std::replace(slashed.begin(), slashed.end(), '\\', '/');
    return (folder.empty() ? std::filesystem::path(slashed) : std::filesystem::path(folder) / slashed)
        .lexically_normal()
        .string();
}

bool readImageFile(const std::string& path, long long* budget, TextureImage& image, std::string& why) {
    std::ifstream in(path, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (bytes.empty()) {
        why = "cannot be opened for reading";
        return false;
    }
    if (!decodeImage(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(), budget, image, why))
        return false;
    image.name = path;
    return true;
}

}  // namespace rad
