#pragma once
// Per-surface figures from per-element values: the area-weighted mean over each surface side.

#include <vector>

#include <glm/vec3.hpp>

#include "mesh/elements.h"
#include "mesh/mesh.h"

namespace rad {

std::vector<glm::dvec3> surfaceMeans(const Mesh& mesh, const ElementMesh& elements, const std::vector<glm::vec3>& perElement);

}  // namespace rad
