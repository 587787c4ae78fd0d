#pragma once
// What of the surface each texel of a lightmap page holds: the parts of faces inside the texel's
// square (its footprint), as pieces the kernel draws points from (kernels/lightmap.cl, the
// TexelPiece record) and the surface area they cover. Exact polygon clipping of each face's
// texel triangle against each texel it touches, in the faces' order, so the lists depend only
// on the layout.

#include <cstdint>
#include <vector>

#include "lightmap/lightmap_layout.h"
#include "mesh/mesh.h"
#include "shared_types.h"

namespace rad {

struct TexelFootprints {
    // The page's texels that hold any surface, in row order (index y * pageSize + x), with
    // ends[i]: one past the last of texel i's pieces (its first: ends[i - 1], or 0).
    std::vector<std::uint32_t> texels;
    std::vector<rad_uint> ends;
    std::vector<TexelPiece> pieces;
    std::vector<TexelAnchor> anchors;  // per listed texel
    std::vector<double> area;          // per listed texel: the surface it covers, m^2
    std::uint64_t sharedTexels = 0;    // texels holding parts of two or more charts
};

TexelFootprints texelFootprints(const LightmapLayout& layout, const Mesh& mesh, std::uint32_t page);

}  // namespace rad
