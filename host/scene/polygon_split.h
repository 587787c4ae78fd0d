#pragma once
// A mesh file's polygon (OBJ's and PLY's faces may have any number of corners) as triangles
// that cover it and nothing outside it. A convex polygon is split as a fan from its first
// corner; one with a reflex corner (an L-shaped panel, a CAD face around a notch), where a fan
// would cover area outside the polygon, is split by ear clipping in the plane of its Newell
// normal. The triangles keep the polygon's winding, so its front stays its front.

#include <array>
#include <cstddef>
#include <vector>

#include <glm/ext/vector_double3.hpp>

namespace rad {

// Triangles over the polygon whose corners, in order, are `corners`, as indices into it. Fewer
// than three corners: none. A polygon that crosses or overlaps itself covers no well-defined
// region: it is split as far as ears are found, then a corner at a time, and where that takes
// long (thousands of corners), the rest as a fan.
std::vector<std::array<std::size_t, 3>> splitPolygon(const std::vector<glm::dvec3>& corners);

}  // namespace rad
