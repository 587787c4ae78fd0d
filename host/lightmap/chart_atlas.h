#pragma once
// A lightmap atlas for a triangle mesh: the triangles are grouped into charts, each chart laid
// flat and scaled to one texel size, and the charts packed into square pages with empty texels
// (the gutter) around each, so that a texel of the lightmap belongs to at most one place on the
// surface and filtering near a chart's edge reads no other chart.
//
// In two steps, the first independent of the texel size (so a search over texel sizes makes
// the charts once):
//  1. Charts (makeCharts). Triangles are first grouped into regions connected across shared
//     edges (the same two vertex positions), of one group (material), with normals within 20
//     degrees of the region's first triangle's and within the crease angle of their neighbour's.
//     Regions then merge, the smallest by area first, into the neighbour they share the longest
//     run of non-crease edges with (a region under 1/4096 of the surface may cross a crease), as
//     long as one cone under the cone angle (below 90 degrees, so no chart closes on itself as a
//     tube or a sphere does) holds both's normals. Each merged region is laid flat by the
//     least-squares conformal map (conformal_map.h), which unrolls a cylinder or a cone without
//     distortion; where that folds, overlaps itself or spreads a triangle's texel density past
//     the stretch limit either way, by projection onto the plane of its mean normal if that does
//     not; else it is cut in two across the direction its normals spread most and each part laid
//     flat the same way. Charts under the attach area then join a neighbour across an edge,
//     creases included, where they unfold onto it about that edge without overlap and within the
//     stretch limit (smallest first, each onto the neighbour whose box that grows least). Each
//     chart is scaled to its surface's area and turned to the smallest rectangle that holds it.
//  2. Pages (tryAtlas). Every chart at the texel size, packed by the texels it touches
//     (chart_packing.h); a chart larger than a page is cut by projection within the page (each
//     part's normals within 15 degrees of its first triangle's, no overlap), and a triangle
//     larger than a page is refused.
// Everything depends only on the triangles, their groups and the options, in order.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "util/error.h"

namespace rad {

struct ChartOptions {
    double creaseDegrees = 45.0;  // neighbours whose normals differ more lie in different charts
    double coneDegrees = 80.0;    // a chart's normals lie within this angle of one axis (under 90)
    // A triangle's texels cover its share of the surface to within this factor, either way.
    double stretchLimit = 2.0;
    // A chart under attachArea (m^2) is attached to a neighbour across an edge they share,
    // creases included, where it unfolds onto it: turned and scaled (by at most 10 %) about that
    // edge to lay it on the neighbour's copy, it stays within the stretch limit, lies on no
    // triangle of either and keeps the neighbour within attachExtent (metres) a side and its box
    // compact. A hexagonal head's sides unroll into one band this way, a tray's rim onto its
    // floor. 0: none.
    double attachArea = 0.0;
    double attachExtent = 0.0;
};

struct AtlasOptions {
    double texelSize = 0.0;         // metres per texel edge; must be positive
    std::uint32_t pageSize = 1024;  // texels per side of a square page
    std::uint32_t gutter = 1;       // empty texels around each chart's texels (two between charts)
    ChartOptions charts;            // for the overloads that make the charts too
};

// The charts of a mesh, flat, in metres: per chart its triangles (ascending) and their corners,
// the chart's smallest corner at the origin.
struct FlatChart {
    std::vector<std::uint32_t> triangles;
    std::vector<std::array<glm::dvec2, 3>> corners;
    glm::dvec2 extent{0.0};  // width >= height
};

struct ChartSet {
    std::vector<FlatChart> charts;
    std::vector<double> area;  // per input triangle, m^2
};

// Throws InputError for options out of range. `groups` (per triangle, or empty for one group):
// charts do not cross from one group to another.
ChartSet makeCharts(const std::vector<std::array<glm::dvec3, 3>>& triangles, const std::vector<std::uint32_t>& groups,
                    const ChartOptions& options);

struct AtlasChart {
    std::vector<std::uint32_t> triangles;  // indices into the input, ascending
    double stretch = 1.0;                  // its triangles' worst stretch (Atlas::largestStretch)
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
    double pagesFilled = 0.0;  // pages in use, the last counted by the rows down to its lowest chart
    // A triangle's stretch: the surface its texels cover over the nominal texelSize^2 each, or
    // the inverse where that is below 1 (so at least 1: how far its texel density strays from the
    // nominal, either way). The worst over the triangles, and the mean weighted by area.
    double largestStretch = 1.0;
    double meanStretch = 1.0;
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
AtlasAttempt tryAtlas(const std::vector<std::array<glm::dvec3, 3>>& triangles, const ChartSet& charts,
                      const AtlasOptions& options);

// tryAtlas on the charts of makeCharts(triangles, {}, options.charts), with a triangle too large
// for a page refused by an InputError that gives its size and a texel size that fits.
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
