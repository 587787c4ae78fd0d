#pragma once
// A linear RGB image, row 0 at the top.

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace rad {

struct Image {
    int width = 0, height = 0;
    std::vector<glm::vec3> pixels;  // radiance, W / m^2 / sr

    const glm::vec3& at(int x, int y) const { return pixels[static_cast<std::size_t>(y) * width + x]; }
};

}  // namespace rad
