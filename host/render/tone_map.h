#pragma once
// From radiance to an 8-bit sRGB preview: an exposure that puts the image's log-average
// luminance at middle grey (Reinhard's key value 0.18), Reinhard's x / (1 + x) per channel,
// then the sRGB transfer curve. The EXR keeps the real values.

#include <cstdint>
#include <vector>

#include "render/image.h"

namespace rad {

std::vector<std::uint8_t> toneMapToSrgb(const Image& image);

// The sRGB transfer curve of a linear value, clamped to [0, 1] first.
float srgb(float linear);

}  // namespace rad
