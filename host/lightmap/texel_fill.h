#pragma once
// What a baked lightmap needs before a viewer filters it:
//   - Gutters: a texel that holds no surface but lies next to one that does takes the mean of
//     its filled neighbours, `gutter` rings deep, so bilinear filtering at a chart's edge reads
//     the chart's own light, not black; the rest of the page is filled from coarser averages
//     (pull-push), so coarser mipmap levels an engine makes are not darkened by black (they
//     still blend neighbouring charts past the gutters; lightmapped.glb asks for none).
//   - Seams: where two charts meet along an edge of the mesh (the same two corners, normals
//     within the crease angle that also bounds a made atlas's charts), the texels on both sides are adjusted by least squares so that bilinear
//     lookups at points along the edge agree from both charts, while each texel holding surface
//     stays near its baked value (mostly the gutter texels move). The irradiance is stitched
//     at every seam, the radiance only where both sides have the same material. Edges between faces whose
//     normals differ more than that are creases, where the light may really change.
// Both depend only on the layout and the values, so they keep the result's determinism.

#include <cstdint>

#include "lightmap/lightmap_layout.h"
#include "lightmap/texel_bake.h"
#include "mesh/mesh.h"

namespace rad {

// Fills empty texels of every page: `rings` rings by neighbours' means, then the rest by pull-push.
void fillGutters(BakedLightmap& lightmap, std::uint32_t rings);

struct SeamReport {
    std::uint64_t edges = 0;    // seam edges stitched
    std::uint64_t samples = 0;  // points along them
    // Root mean square over those points of the difference between the two sides' bilinear
    // lookups of the irradiance's luminance, before and after (W / m^2).
    double mismatchBefore = 0.0, mismatchAfter = 0.0;
};

// Points along each seam edge and the difference of the two sides' lookups there (bilinear, as a
// viewer filters; texel centres at i + 0.5). For tests and the report.
struct SeamPoint {
    std::uint32_t edge = 0;  // which seam edge, numbered from 0
    std::uint32_t pageA = 0, pageB = 0;
    glm::dvec2 a{0.0}, b{0.0};  // texel coordinates of the same surface point in each chart
    bool sameMaterial = true;   // the faces on both sides have one material
};
std::vector<SeamPoint> seamPoints(const LightmapLayout& layout, const Mesh& mesh, double creaseDegrees = 45.0);
glm::vec3 bilinear(const std::vector<glm::vec3>& page, std::uint32_t size, glm::dvec2 at);

SeamReport stitchSeams(BakedLightmap& lightmap, const LightmapLayout& layout, const Mesh& mesh,
                       double creaseDegrees = 45.0);

}  // namespace rad
