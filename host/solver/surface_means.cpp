#include "solver/surface_means.h"

namespace rad {

std::vector<glm::dvec3> surfaceMeans(const Mesh& mesh, const ElementMesh& elements, const std::vector<glm::vec3>& perElement) {
    std::vector<glm::dvec3> sum(mesh.surfaces.size(), glm::dvec3(0.0));
    std::vector<double> area(mesh.surfaces.size(), 0.0);
    const auto& list = elements.elements();
    for (std::size_t e = 0; e < list.size(); ++e) {
        const std::uint32_t s = mesh.patches[list[e].patch].surface;
        sum[s] += static_cast<double>(list[e].area) * glm::dvec3(perElement[e]);
        area[s] += list[e].area;
    }
    for (std::size_t s = 0; s < sum.size(); ++s)
        if (area[s] > 0.0) sum[s] /= area[s];
    return sum;
}

}  // namespace rad
