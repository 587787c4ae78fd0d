#pragma once
// Tangent frames for normal maps (glTF's normalTexture): where a file gives no TANGENT, glTF asks
// viewers for MikkTSpace's tangents, the frame a normal map was baked against. These follow
// MikkTSpace's construction for the meshes glTF holds (vertices already split where texture
// coordinates or normals part): each triangle's direction of increasing u, made perpendicular to
// each corner's normal and summed over the triangles around a vertex weighted by their angle
// there, then made unit and perpendicular; the sign w says on which side of the tangent the
// texture's "up" lies (-dP/dv, glTF's v running down the image), so the bitangent is
// cross(normal, tangent) * w, as glTF defines it. MikkTSpace also splits a vertex whose triangles
// disagree about w (mirrored texture coordinates meeting at it); here such a vertex takes the
// sign of the larger weight.

#include <cstddef>
#include <vector>

#include <glm/vec4.hpp>

#include "scene/scene.h"

namespace rad {

// Tangents (xyz unit, w = +-1) for the vertices of `surface` that the triangles flagged in
// `wanted` use, from texture coordinate set `texCoord` and the surface's normals (a corner of a
// surface without NORMAL takes its triangle's own). Other vertices keep what `tangents` holds
// (zero where nothing has set it). A vertex whose triangles' coordinates are all degenerate
// (no u direction) gets some unit vector perpendicular to its normal, w = 1. A vertex that
// already has a frame (w != 0: the file's TANGENT, or one generated for another set) keeps it.
void generateTangents(const Surface& surface, int texCoord, const std::vector<bool>& wanted,
                      std::vector<glm::vec4>& tangents);

// Tangents where a normal map of `materials` needs them and the file gave none, from the texture
// coordinate set each map reads (a triangle without that set reads the map's (0, 0) texel in some
// frame about its normal).
void frameNormalMaps(Surface& surface, const std::vector<Material>& materials);

}  // namespace rad
