#pragma once
// The solution per element, for users who integrate it themselves (power on a region, heat
// loads, comparisons with other tools): one row per element with its surface, patch, level,
// centroid and normal (scene coordinates, metres), area (m^2), reflectance and radiosity
// B (W/m^2, per channel). The received irradiance is (B - E) / rho where rho > 0.

#include <ostream>
#include <vector>

#include <glm/vec3.hpp>

#include "mesh/elements.h"
#include "prepared/prepared_scene.h"

namespace rad {

void writeElementCsv(std::ostream& out, const PreparedScene& scene, const ElementMesh& elements,
                     const std::vector<glm::vec3>& radiosity);

}  // namespace rad
