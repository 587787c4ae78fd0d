#pragma once
// Images out: OpenEXR (32-bit float RGB, the real radiance) and a PNG preview (tone-mapped
// sRGB). Both are written whole or not at all.

#include <string>

#include "render/image.h"

namespace rad {

void writeExr(const std::string& path, const Image& image);
void writePngPreview(const std::string& path, const Image& image);

// Reads an EXR's R, G, B channels (for tests and tools). Throws RuntimeFailure on failure.
Image readExr(const std::string& path);

}  // namespace rad
