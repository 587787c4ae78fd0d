#pragma once
// A lightmap atlas for a triangle mesh (issue 16, part 1): the triangles are grouped into
// charts, each chart laid flat and scaled to one texel size, and the charts packed into square
// pages with empty texels (the gutter) around each, so that a texel of the lightmap belongs to
// at most one place on the surface and filtering near a chart's edge reads no other chart.
//
// A chart grows from its first triangle across shared edges (the same two vertex positions)
// while the new triangle's normal lies within a cone about the first one's, and it is laid flat
// by orthographic projection onto the plane of that normal. A flat region thus keeps its shape
// exactly; a gently curved one is compressed along its tilt by cos(tilt), so a texel covers at
// most 1 / cos(cone) times its nominal area (the stretch the atlas reports). A triangle that
// would overlap the chart's projection (a fold, a spiral ramp) or grow it past a page starts
// another chart instead. Everything depends only on the triangles and the options, in order.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "util/error.h"

namespace rad {

struct AtlasOptions {
    double texelSize = 0.0;         // metres per texel edge; must be positive
    std::uint32_t pageSize = 1024;  // texels per side of a square page
    std::uint32_t gutter = 2;       // empty texels kept between a chart and anything else
    double coneDegrees = 15.0;      // a chart's normals lie within this angle of its first one
};

struct AtlasChart {
    std::vector<std::uint32_t> triangles;  // indices into the input, ascending
    glm::dvec3 normal{0.0};                // the plane the chart is projected onto
    std::uint32_t page = 0;
    std::uint32_t x = 0, y = 0;  // the chart's texel rectangle in its page (gutter outside it)
    std::uint32_t width = 0, height = 0;
};

struct Atlas {
    double texelSize = 0.0;
    std::uint32_t pageSize = 0, gutter = 0, pages = 0;
    std::vector<AtlasChart> charts;
    std::vector<std::uint32_t> chartOf;             // per input triangle
    std::vector<std::array<glm::dvec2, 3>> texels;  // per triangle corner: texel coordinates in its page
    double areaUse = 0.0;                           // the triangles' area in texels over all pages' texels
    double largestStretch = 1.0;  // the most surface area a texel covers, over its nominal texelSize^2
};

// One triangle alone larger than a page at the options' texel size: which, how many texels its
// box spans, and a texel size at which it fits.
struct OversizedTriangle {
    std::uint32_t triangle = 0;
    double span = 0.0;
    double fittingTexelSize = 0.0;
};

// The atlas, or (atlas empty) the first triangle too large for a page: a search over texel or
// page sizes asks this and moves on. Throws InputError only for options out of range.
struct AtlasAttempt {
    std::optional<Atlas> atlas;
    OversizedTriangle oversized;
};
AtlasAttempt tryAtlas(const std::vector<std::array<glm::dvec3, 3>>& triangles, const AtlasOptions& options);

// tryAtlas, with a triangle too large for a page refused by an InputError that gives its size
// and a texel size that fits.
Atlas buildAtlas(const std::vector<std::array<glm::dvec3, 3>>& triangles, const AtlasOptions& options);

// What a lightmap UV set given with the scene (glTF's TEXCOORD_1) is worth: a lightmap needs
// every triangle to own its texels, so no two triangles may overlap in UV space and none may
// be degenerate there. Touching along an edge or at a corner is not overlap.
struct UvLayoutCheck {
    std::uint64_t overlappingPairs = 0;                  // pairs whose interiors overlap
    std::uint64_t degenerate = 0;                        // triangles of no UV area (or with coordinates not finite)
    std::vector<std::array<std::uint32_t, 2>> examples;  // the first few overlapping pairs, in order
    bool usable() const { return overlappingPairs == 0 && degenerate == 0; }
};

UvLayoutCheck checkUvLayout(const std::vector<std::array<glm::dvec2, 3>>& uv, std::size_t maxExamples = 8);

}  // namespace rad
