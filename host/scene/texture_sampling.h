#pragma once
// Reading textures on the host: sRGB decoding, wrap modes, bilinear filtering, and a texture's
// mean over a triangle of texture space (what an element's reflectance is). The camera pass
// does the same on the device (kernels/texture.h), from the same rules.

#include <cstdint>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "scene/scene.h"

namespace rad {

// The linear value of an sRGB-encoded byte (IEC 61966-2-1), rounded to float.
float srgbToLinear(std::uint8_t value);

// Texture coordinates after KHR_texture_transform.
glm::vec2 transformedUv(const TextureRef& ref, glm::vec2 uv);

// The texture at `uv` (before its transform): linear RGB (sRGB decoded, unless the reference is
// to data, TextureRef::linear; then filtered) and alpha.
glm::vec4 sampleTexture(const TextureImage& image, const TextureRef& ref, glm::vec2 uv);

// The texture's mean over the triangle (a, b, c) of texture coordinates (before the transform),
// by the midpoint rule on k x k similar sub-triangles, k chosen so that there are about four
// points per texel the triangle covers (at least 16 points, at most `mostPoints`).
glm::vec4 meanOverTriangle(const TextureImage& image, const TextureRef& ref, glm::vec2 a, glm::vec2 b, glm::vec2 c,
                           double mostPoints = 16384.0);

}  // namespace rad
