#include "scene/image_decode.h"

#include <climits>

#include <stb_image.h>

namespace rad {

bool decodeImage(const unsigned char* bytes, std::size_t size, long long* budget, TextureImage& image, std::string& why) {
    image.width = image.height = 0;
    image.rgba.clear();
    // PNG or JPEG only: stb_image reads more formats (HDR, among others, tone-mapped), which glTF
    // does not allow and which would be misread as sRGB.
    const bool png = size >= 8 && bytes[0] == 0x89 && bytes[1] == 'P' && bytes[2] == 'N' && bytes[3] == 'G';
    const bool jpeg = size >= 3 && bytes[0] == 0xFF && bytes[1] == 0xD8 && bytes[2] == 0xFF;
    const int length = static_cast<int>(std::min<std::size_t>(size, INT_MAX));
    int width = 0, height = 0, channels = 0;
    if (!(png || jpeg) || !stbi_info_from_memory(bytes, length, &width, &height, &channels)) {
        why = "is not a PNG or JPEG this program can read";
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
    unsigned char* texels = stbi_load_from_memory(bytes, length, &width, &height, &channels, 4);
    if (!texels) {
        why = std::string("cannot be decoded (") + stbi_failure_reason() + ")";
        return false;
    }
    image.width = width;
    image.height = height;
    image.rgba.assign(texels, texels + static_cast<std::size_t>(width) * height * 4);
    stbi_image_free(texels);
    return true;
}

}  // namespace rad
