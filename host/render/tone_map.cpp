#include "render/tone_map.h"

#include <algorithm>
#include <cmath>

namespace rad {

float srgb(float linear) {
    linear = std::clamp(linear, 0.0f, 1.0f);
    return linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

std::vector<std::uint8_t> toneMapToSrgb(const Image& image) {
    double logSum = 0.0;
    std::size_t lit = 0;
    for (const glm::vec3& p : image.pixels) {
        const double y = 0.2126 * p.x + 0.7152 * p.y + 0.0722 * p.z;
        if (y > 1e-6) {
            logSum += std::log(y);
            ++lit;
        }
    }
    const float exposure = lit > 0 ? static_cast<float>(0.18 / std::exp(logSum / static_cast<double>(lit))) : 1.0f;
    std::vector<std::uint8_t> out(image.pixels.size() * 3);
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const float x = std::max(0.0f, image.pixels[i][c] * exposure);
            out[3 * i + c] = static_cast<std::uint8_t>(std::lround(255.0f * srgb(x / (1.0f + x))));
        }
    return out;
}

}  // namespace rad
