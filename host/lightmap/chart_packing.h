#pragma once
// Packing a lightmap atlas's charts into square pages by their texels, not their boxes (as
// xatlas and the lightmappers artists use do): each chart claims the texels its triangles
// touch, grown by the gutter, and takes the first place, row by row from the top of the first
// page that has room, where its claim meets no other chart's, lying as it is or turned by one,
// two or three quarters, whichever comes first (a concave chart may nest into a gap one way
// round only). Charts go by their box's perimeter, longest first, so small ones fill the gaps
// that large ones leave (an L's inside, the space between a chart and its box).
//
// Two charts' claims never meet, so the texels the triangles of two charts touch lie at least
// 2 * gutter texels apart, and a chart's at least `gutter` texels from the page's edge: with
// one gutter texel, a bilinear lookup inside a chart reads its own texels and its own gutter,
// which gutter filling gives the chart's light. Depends only on the charts, in order.

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

namespace rad {

// A chart to pack: its triangles' corners in texels, inside [0, width] x [0, height].
struct ChartTexels {
    std::vector<std::array<glm::dvec2, 3>> corners;
    std::uint32_t width = 1, height = 1;
};

// Where a chart went: its page and the corner of its box there, turned by 0 to 3 quarter turns
// counter-clockwise ((x, y) -> (height - y, x) each, its box then height x width).
struct ChartPlacement {
    std::uint32_t page = 0, x = 0, y = 0;
    std::uint8_t quarterTurns = 0;
};

// Each chart's box (turned or not) must fit a page inside its gutters: 2 * gutter + width
// <= pageSize, and the same for the height. Returns the placements and sets `pages` and, where
// given, `filled`: the pages in use, the last counted by the rows down to its lowest claim's.
std::vector<ChartPlacement> packChartTexels(const std::vector<ChartTexels>& charts, std::uint32_t pageSize,
                                            std::uint32_t gutter, std::uint32_t* pages, double* filled = nullptr);

// The texels whose square meets a triangle's interior (touching along an edge or at a corner
// does not count), by the separating axis test, as (x, y) pairs in ascending order of y, x.
std::vector<std::array<std::int64_t, 2>> touchedTexels(const std::array<glm::dvec2, 3>& triangle);

}  // namespace rad
