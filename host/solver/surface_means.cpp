#include "solver/surface_means.h"

namespace rad {

std::vector<glm::dvec3> surfaceMeans(const Mesh& mesh, const std::vector<glm::vec3>& perPatch) {
    std::vector<glm::dvec3> means(mesh.surfaces.size(), glm::dvec3(0.0));
    for (std::size_t s = 0; s < mesh.surfaces.size(); ++s) {
        const MeshSurface& surface = mesh.surfaces[s];
        glm::dvec3 sum(0.0);
        double area = 0.0;
        for (std::uint32_t k = 0; k < surface.patchCount; ++k) {
            const Patch& p = mesh.patches[surface.firstPatch + k];
            sum += static_cast<double>(p.area) * glm::dvec3(perPatch[surface.firstPatch + k]);
            area += p.area;
        }
        if (area > 0.0) means[s] = sum / area;
    }
    return means;
}

}  // namespace rad
