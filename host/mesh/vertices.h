#pragma once
// Vertices for smooth shading: patch corners welded where they coincide on the same surface
// side and the patches' normals agree (within the crease angle). A vertex's value is the
// area-weighted average of the patches around it, so interpolation is smooth within a surface
// and never blends across surfaces or creases.

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "mesh/mesh.h"

namespace rad {

struct MeshVertices {
    std::vector<glm::vec3> positions;
    std::vector<std::uint32_t> surface;                       // the surface side each vertex belongs to
    std::vector<std::array<std::uint32_t, 3>> patchCorners;   // per patch, in the patch's corner order
};

MeshVertices weldVertices(const Mesh& mesh, float creaseDegrees = 30.0f);

// Area-weighted average of per-patch values at each vertex.
std::vector<glm::vec3> vertexValues(const Mesh& mesh, const MeshVertices& vertices, const std::vector<glm::vec3>& perPatch);

}  // namespace rad
