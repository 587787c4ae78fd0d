#pragma once
// Vertices for smooth shading: element corners welded where they coincide on the same surface
// side and the elements' normals agree (within the crease angle), or, where the file gives vertex
// normals (NORMAL), where those agree: the author's smooth and hard edges (vertices.cpp says
// how far). A vertex's value comes from
// the elements around it, so interpolation is smooth within a surface and never blends across
// surfaces or creases. Where an element meets finer ones, the corners
// of those that lie on its edge (T-vertices) take the values the coarse edge interpolates, so
// the shading is continuous across the edge and shows no crack.

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "mesh/elements.h"
#include "mesh/mesh.h"

namespace rad {

struct MeshVertices {
    std::vector<glm::vec3> positions;
    std::vector<std::uint32_t> surface;                       // the surface side each vertex belongs to
    std::vector<std::array<std::uint32_t, 3>> corners;        // per element, in its corner order
    // T-vertices: `vertex` lies halfway along the coarse edge (a, b) and takes the mean of their
    // values. In order: coarser edges first, so nested T-vertices resolve top-down.
    struct TVertex {
        std::uint32_t vertex, a, b;
    };
    std::vector<TVertex> tVertices;
    // Per element, the T-vertices on its edges, each edge's in order from its first corner:
    // edgePoints[e][k] lies on the edge from corner k to corner k + 1. Empty for most elements.
    std::vector<std::array<std::vector<std::uint32_t>, 3>> edgePoints;
};

MeshVertices weldVertices(const Mesh& mesh, const ElementMesh& elements, float creaseDegrees = 30.0f);

// Per vertex, a plane fitted to the values of the elements around it, read at the vertex
// (exact for linearly varying light on any mix of element sizes), then the T-vertex rule.
std::vector<glm::vec3> vertexValues(const ElementMesh& elements, const MeshVertices& vertices,
                                    const std::vector<glm::vec3>& perElement);

}  // namespace rad
