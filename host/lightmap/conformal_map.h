#pragma once
// A chart of triangles laid flat by the least-squares conformal map (Levy, Petitjean, Ray and
// Maillot 2002, "Least squares conformal maps for automatic texture atlas generation"): the
// map, linear on each triangle, that comes closest to keeping angles (the Cauchy-Riemann
// equations in each triangle's own plane, weighted by its area), with two vertices pinned. A
// developable surface (a plane, a cylinder, a cone) is unrolled without distortion; a curved
// one is spread with area distortion but no shear. Vertices are shared where triangles meet at
// the same position, so the chart is one piece as long as its triangles meet along edges.
//
// The map is scaled so that the chart's flat area equals its surface area (one texel density on
// average over the chart). It may still fold or overlap on charts far from a disc (a spiral
// ramp, a closed tube): the caller checks what it gets.

#include <array>
#include <optional>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace rad {

// Per triangle, its corners in the plane (metres), or nothing where the solve fails (a chart of
// no area, or coordinates not finite).
std::optional<std::vector<std::array<glm::dvec2, 3>>> conformalMap(
    const std::vector<std::array<glm::dvec3, 3>>& triangles);

}  // namespace rad
