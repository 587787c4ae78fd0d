#pragma once
// Where each face of the mesh lies in the lightmap (issue 16): a page and its corners' texel
// coordinates there (texel (i, j) spans [i, i + 1] x [j, j + 1]; row 0 is the image's top, as
// glTF's texture coordinate v = 0 is). Either the UV set the scene brings for it (TEXCOORD_1,
// [0, 1] over one page) where every face has one and no two faces share texels, or an atlas
// made here (lightmap/chart_atlas.h).

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "lightmap/chart_atlas.h"
#include "mesh/mesh.h"
#include "scene/scene.h"

namespace rad {

struct LightmapOptions {
    // Metres per texel edge; 0: one that puts the whole atlas on one page, within 0.01 % of one
    // that does not (found by bisection).
    double texelSize = 0.0;
    // Texels per side of a square page (8 .. 8192). 0: 1024, or with a texel size given, the
    // smallest power of two from 64 to 4096 that holds the atlas on one page (else pages of 4096).
    std::uint32_t pageSize = 0;
    std::uint32_t gutter = 1;   // empty texels around each chart of a made atlas
    ChartOptions charts;        // how a made atlas's charts are grown and laid flat
    // Where charts.attachArea is 0: charts under this share of a page's texels (64 x 64 of 1024
    // x 1024) join a neighbour they unfold onto (ChartOptions::attachArea), at the texel size
    // given or one filling 65 % of the page, up to an eighth of a page a side. 0: none.
    double attachShare = 1.0 / 256.0;
    enum class Uv { automatic, scene, atlas };
    // automatic: the scene's TEXCOORD_1 where usable, else a made atlas (the layout's note says
    // why); scene: TEXCOORD_1 or an InputError saying why not; atlas: always a made one.
    Uv uv = Uv::automatic;
};

struct LightmapLayout {
    bool fromScene = false;  // TEXCOORD_1, or a made atlas
    // Why a made atlas where the scene has a TEXCOORD_1, or that a texel size given for an atlas
    // was not used; empty otherwise.
    std::string note;
    std::uint32_t pageSize = 0, pages = 0, charts = 0;
    // Metres per texel edge: the atlas's; with the scene's UVs, the median over faces (by area).
    double texelSize = 0.0;
    double areaUse = 0.0;                           // the faces' texel area over all pages' texels
    // How far a face's texel density strays from the nominal, either way (Atlas::largestStretch):
    // the worst face's, and the mean over the surface.
    double largestStretch = 1.0, meanStretch = 1.0;
    std::vector<std::uint32_t> pageOf;              // per face
    std::vector<std::uint32_t> chartOf;             // per face: its chart, numbered from 0
    std::vector<std::array<glm::dvec2, 3>> texels;  // per face corner (Face::p's order)
};

// Throws InputError for options out of range, a scene UV set refused under Uv::scene, or a
// face too large for a page (with the texel size that fits).
LightmapLayout layoutLightmap(const Scene& scene, const Mesh& mesh, const LightmapOptions& options);

// The UV set a layout gives the scene's surface s, per vertex (TEXCOORD_1's [0, 1] page
// coordinates) with, per triangle, its corners' vertex indices into that list: the surface's own
// vertices split where a vertex sits at different places of the lightmap (a chart's edge).
struct LightmapUvs {
    std::vector<std::uint32_t> vertexOf;  // per new vertex: the surface's vertex it copies
    std::vector<glm::vec2> uv;            // per new vertex
    std::vector<std::uint32_t> page;      // per triangle
    std::vector<std::array<std::uint32_t, 3>> triangles;
};
LightmapUvs lightmapUvs(const Scene& scene, const Mesh& mesh, const LightmapLayout& layout, std::size_t surface);

}  // namespace rad
