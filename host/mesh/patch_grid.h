#pragma once
// The regular subdivision of a triangle (v0, v1, v2) into n * n similar triangles. Grid point
// (a, b) is v0 + (a / n)(v1 - v0) + (b / n)(v2 - v0). Row b holds the "up" triangles
// (a, b) (a+1, b) (a, b+1) for a = 0..n-1-b and, between them, the "down" triangles
// (a+1, b) (a+1, b+1) (a, b+1) for a = 0..n-2-b. Both keep the parent's orientation.
// Index within the triangle: 2nb - b^2 + 2a + (down ? 1 : 0), written once for the host and the
// kernels (kernels/shared_math.h: rad_grid_index); kernels/patch_lookup.h finds the cell of a
// hit's barycentric coordinates.

#include <array>
#include <cstdint>

#include <glm/vec3.hpp>

#include "shared_math.h"

namespace rad {

struct GridCell {
    std::uint32_t a = 0, b = 0;
    bool down = false;
};

inline std::uint32_t gridIndex(std::uint32_t n, GridCell cell) { return rad_grid_index(n, cell.a, cell.b, cell.down ? 1u : 0u); }

// The grid point (a, b) of the triangle, computed in double so that neighbouring cells get
// bitwise the same corners.
inline glm::vec3 gridPoint(const std::array<glm::vec3, 3>& t, std::uint32_t n, std::uint32_t a, std::uint32_t b) {
    const glm::dvec3 v0(t[0]);
    const glm::dvec3 p = v0 + (double(a) / n) * (glm::dvec3(t[1]) - v0) + (double(b) / n) * (glm::dvec3(t[2]) - v0);
    return glm::vec3(p);
}

inline std::array<glm::vec3, 3> gridCellCorners(const std::array<glm::vec3, 3>& t, std::uint32_t n, GridCell c) {
    if (!c.down) return {gridPoint(t, n, c.a, c.b), gridPoint(t, n, c.a + 1, c.b), gridPoint(t, n, c.a, c.b + 1)};
    return {gridPoint(t, n, c.a + 1, c.b), gridPoint(t, n, c.a + 1, c.b + 1), gridPoint(t, n, c.a, c.b + 1)};
}

// Calls f(cell) for every cell in index order.
template <typename F>
void forEachGridCell(std::uint32_t n, F&& f) {
    for (std::uint32_t b = 0; b < n; ++b)
        for (std::uint32_t a = 0; a + b < n; ++a) {
            f(GridCell{a, b, false});
            if (a + b + 1 < n) f(GridCell{a, b, true});
        }
}

}  // namespace rad
