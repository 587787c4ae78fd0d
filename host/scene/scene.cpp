#include "scene/scene.h"

#include <glm/geometric.hpp>

namespace rad {

void Bounds::extend(const glm::vec3& p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
}

double Bounds::diagonal() const {
    if (empty()) return 0.0;
    return glm::length(glm::dvec3(hi) - glm::dvec3(lo));
}

std::size_t Scene::triangleCount() const {
    std::size_t n = 0;
    for (const Surface& s : surfaces) n += s.triangles.size();
    return n;
}

Bounds Scene::bounds() const {
    Bounds b;
    for (const Surface& s : surfaces)
        for (const auto& t : s.triangles)
            for (std::uint32_t v : t) b.extend(s.positions[v]);
    return b;
}

bool Scene::anyEmitter() const {
    return anyEmissiveSurface() || !lights.empty() || sky.x > 0.0f || sky.y > 0.0f || sky.z > 0.0f ||
           environment != nullptr;
}

bool Scene::anyEmissiveSurface() const {
    for (const Surface& s : surfaces)
        for (int m : s.triangleMaterial)
            if (materials[static_cast<std::size_t>(m)].emits()) return true;
    return false;
}

}  // namespace rad
