#include "scene/texture_sampling.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace rad {
namespace {

const std::array<float, 256>& srgbTable() {
    static const std::array<float, 256> table = [] {
        std::array<float, 256> t{};
        for (int i = 0; i < 256; ++i) {
            const double c = i / 255.0;
            t[static_cast<std::size_t>(i)] =
                static_cast<float>(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
        }
        return t;
    }();
    return table;
}

// The texel index along one axis of `size` texels for the integer texel coordinate i.
int wrapped(int i, int size, TextureRef::Wrap wrap) {
    switch (wrap) {
        case TextureRef::Wrap::ClampToEdge:
            return std::clamp(i, 0, size - 1);
        case TextureRef::Wrap::MirroredRepeat: {
            const int period = 2 * size;
            int m = i % period;
            if (m < 0) m += period;
            return m < size ? m : period - 1 - m;
        }
        case TextureRef::Wrap::Repeat:
        default: {
            int m = i % size;
            return m < 0 ? m + size : m;
        }
    }
}

// A coordinate brought into one period of its wrap mode first, so texel indices stay small
// whatever the coordinate (clamping needs only [0, 1] and a margin).
double wrapCoordinate(double t, TextureRef::Wrap wrap) {
    if (!std::isfinite(t)) return 0.0;  // a transform that overflowed: read the first texel, not UB
    switch (wrap) {
        case TextureRef::Wrap::ClampToEdge:
            return std::clamp(t, -1.0, 2.0);
        case TextureRef::Wrap::MirroredRepeat:
            return t - 2.0 * std::floor(0.5 * t);
        case TextureRef::Wrap::Repeat:
        default:
            return t - std::floor(t);
    }
}

glm::vec4 texel(const TextureImage& image, int x, int y, bool linear) {
    const std::uint8_t* p = &image.rgba[(static_cast<std::size_t>(y) * image.width + x) * 4];
    if (linear) return {p[0] / 255.0f, p[1] / 255.0f, p[2] / 255.0f, p[3] / 255.0f};
    const auto& table = srgbTable();
    return {table[p[0]], table[p[1]], table[p[2]], p[3] / 255.0f};
}

}  // namespace

float srgbToLinear(std::uint8_t value) {
    return srgbTable()[value];
}

glm::vec2 transformedUv(const TextureRef& ref, glm::vec2 uv) {
    const glm::vec3 t = ref.transform * glm::vec3(uv, 1.0f);
    return {t.x, t.y};
}

glm::vec4 sampleTexture(const TextureImage& image, const TextureRef& ref, glm::vec2 uv) {
    if (image.width <= 0 || image.height <= 0) return glm::vec4(1.0f);
    const glm::vec2 t = transformedUv(ref, uv);
    // Texel centres sit at half-integers: (u W - 1/2, v H - 1/2) in texel units.
    const double x = wrapCoordinate(t.x, ref.wrapS) * image.width - 0.5;
    const double y = wrapCoordinate(t.y, ref.wrapT) * image.height - 0.5;
    if (ref.nearest) {
        const int ix = wrapped(static_cast<int>(std::floor(x + 0.5)), image.width, ref.wrapS);
        const int iy = wrapped(static_cast<int>(std::floor(y + 0.5)), image.height, ref.wrapT);
        return texel(image, ix, iy, ref.linear);
    }
    const double fx = std::floor(x), fy = std::floor(y);
    const auto wx = static_cast<float>(x - fx), wy = static_cast<float>(y - fy);
    const int x0 = wrapped(static_cast<int>(fx), image.width, ref.wrapS);
    const int x1 = wrapped(static_cast<int>(fx) + 1, image.width, ref.wrapS);
    const int y0 = wrapped(static_cast<int>(fy), image.height, ref.wrapT);
    const int y1 = wrapped(static_cast<int>(fy) + 1, image.height, ref.wrapT);
    return (1.0f - wy) * ((1.0f - wx) * texel(image, x0, y0, ref.linear) + wx * texel(image, x1, y0, ref.linear)) +
           wy * ((1.0f - wx) * texel(image, x0, y1, ref.linear) + wx * texel(image, x1, y1, ref.linear));
}

glm::vec4 meanOverTriangle(const TextureImage& image, const TextureRef& ref, glm::vec2 a, glm::vec2 b, glm::vec2 c,
                           double mostPoints) {
    if (image.width <= 0 || image.height <= 0) return glm::vec4(1.0f);
    const glm::vec2 ta = transformedUv(ref, a), tb = transformedUv(ref, b), tc = transformedUv(ref, c);
    const double texels =
        0.5 *
        std::fabs(static_cast<double>(tb.x - ta.x) * (tc.y - ta.y) - static_cast<double>(tc.x - ta.x) * (tb.y - ta.y)) *
        image.width * image.height;
    const double points = std::clamp(4.0 * texels, std::min(64.0, mostPoints), std::max(16.0, mostPoints));
    const int k = static_cast<int>(std::ceil(std::sqrt(points)));
    glm::dvec4 sum(0.0);
    for (int row = 0; row < k; ++row)
        for (int i = 0; i + row < k; ++i) {
            for (const double third : {1.0 / 3.0, 2.0 / 3.0}) {
                if (third > 0.5 && i + row + 1 >= k) continue;  // the inverted cells: one fewer per row
                const double u = (i + third) / k, v = (row + third) / k;
                const glm::vec2 uv = a + static_cast<float>(u) * (b - a) + static_cast<float>(v) * (c - a);
                sum += glm::dvec4(sampleTexture(image, ref, uv));
            }
        }
    return glm::vec4(sum / static_cast<double>(k * k));
}

}  // namespace rad
