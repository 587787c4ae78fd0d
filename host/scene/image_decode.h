#pragma once
// Texture images from their bytes: PNG and JPEG (by their first bytes, not their names),
// decoded by stb_image, and WebP (EXT_texture_webp), by libwebp, into 8-bit RGBA, within a
// budget of texels, for glTF's images and the maps an OBJ's MTL names alike.

#include <cstddef>
#include <string>

#include "scene/scene.h"

namespace rad {

// Texels beyond this are refused (a 16k x 16k image is 1 GiB of RGBA): a corrupt or hostile
// header must not make the loader allocate without bound.
inline constexpr long long kMostImageTexels = 1LL << 28;

// Decodes `bytes` into image.width, height and rgba. Where they are no PNG, JPEG or WebP image
// the decoders can read, or take more texels than kMostImageTexels or than *budget (where given: the texels a
// file's images may still take, which this one's reduce), returns false with *why saying so
// ("is not a PNG, JPEG or WebP image this program can read") and leaves the image empty.
bool decodeImage(const unsigned char* bytes, std::size_t size, long long* budget, TextureImage& image, std::string& why);

// Where a mesh file's image named `name` lies: relative to `folder` (the mesh file's), its
// folders separated by slashes or, as Windows programs write them, backslashes.
std::string imagePath(const std::string& folder, const std::string& name);

// Reads and decodes the image file `path` into `image` (its name the path), as decodeImage;
// false with *why where it cannot be opened or decoded.
bool readImageFile(const std::string& path, long long* budget, TextureImage& image, std::string& why);

}  // namespace rad
