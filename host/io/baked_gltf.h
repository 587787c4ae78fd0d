#pragma once
// The lit scene as a binary glTF: every surface side as a mesh of its elements, with the
// radiance (B / pi, linear, W / m^2 / sr) at each vertex in COLOR_0 and an unlit material
// (KHR_materials_unlit), so a glTF viewer shows the baked light. Radiance is not clamped:
// emitters exceed 1, and viewers clip them to white.

#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "mesh/elements.h"
#include "mesh/mesh.h"
#include "mesh/vertices.h"

namespace rad {

// `origin`: where the mesh's coordinates are relative to (Scene::origin); the file puts the
// surfaces under one root node translated there, so they sit where the scene had them.
// Elements with T-vertices on their edges are split into a fan around their centroid, so the
// triangles meet without cracks.
void writeBakedGltf(const std::string& path, const Mesh& mesh, const ElementMesh& elements, const MeshVertices& vertices,
                    const std::vector<glm::vec3>& vertexRadiance, const glm::dvec3& origin);

}  // namespace rad
