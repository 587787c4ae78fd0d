#include "scene/world_surfaces.h"

#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "util/error.h"

namespace rad {

namespace {

// A triangle whose normal float arithmetic cannot tell (zero area, or angles below ~1e-7 rad).
bool isDegenerate(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    const glm::dvec3 e1 = glm::dvec3(b) - glm::dvec3(a);
    const glm::dvec3 e2 = glm::dvec3(c) - glm::dvec3(a);
    const double cross = glm::length(glm::cross(e1, e2));
    return !(cross > 1e-7 * glm::length(e1) * glm::length(e2));
}

bool withinFloatReach(const glm::dvec3& p) {
    return std::fabs(p.x) < 1e37 && std::fabs(p.y) < 1e37 && std::fabs(p.z) < 1e37;
}

}  // namespace

glm::vec3 relativeToOrigin(const glm::dvec3& world, const Scene& scene, const std::string& path,
                           const std::string& what) {
    const glm::dvec3 relative = world - scene.origin;
    if (!withinFloatReach(relative)) throw FileError(path, what + " lies beyond single precision from the scene");
    return glm::vec3(relative);
}

void placeSurfaces(std::vector<WorldSurface>& building, const std::string& path, Scene& scene) {
    glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
    for (const WorldSurface& b : building)
        for (const auto& t : b.surface.triangles)
            for (std::uint32_t v : t) {
                lo = glm::min(lo, b.world[v]);
                hi = glm::max(hi, b.world[v]);
            }
    const glm::dvec3 origin = building.empty() ? glm::dvec3(0.0) : 0.5 * lo + 0.5 * hi;
    scene.origin = origin;
    std::size_t degenerate = 0;
    for (WorldSurface& b : building) {
        Surface& surface = b.surface;
        surface.positions.resize(b.world.size());
        for (auto& coords : surface.texCoords)
            if (!coords.empty()) coords.resize(b.world.size(), glm::vec2(0.0f));
        if (!surface.normals.empty()) surface.normals.resize(b.world.size(), glm::vec3(0.0f));
        if (!surface.colors.empty()) surface.colors.resize(b.world.size(), glm::vec3(1.0f));
        for (std::size_t i = 0; i < b.world.size(); ++i) {
            const glm::dvec3 relative = b.world[i] - origin;
            if (!withinFloatReach(relative))
                throw FileError(path, "the scene spans more than single precision can hold (a vertex of '" +
                                          surface.name + "' lies beyond 1e37 m of its centre)");
            surface.positions[i] = glm::vec3(relative);
        }
        std::vector<std::array<std::uint32_t, 3>> triangles;
        std::vector<int> materials;
        for (std::size_t t = 0; t < surface.triangles.size(); ++t) {
            const auto& tri = surface.triangles[t];
            if (isDegenerate(surface.positions[tri[0]], surface.positions[tri[1]], surface.positions[tri[2]])) {
                ++degenerate;
                continue;
            }
            triangles.push_back(tri);
            materials.push_back(surface.triangleMaterial[t]);
        }
        surface.triangles = std::move(triangles);
        surface.triangleMaterial = std::move(materials);
        if (!surface.triangles.empty()) scene.surfaces.push_back(std::move(surface));
    }
    if (degenerate > 0)
        scene.warnings.push_back(std::to_string(degenerate) + " degenerate (zero-area) triangle(s) dropped");
}

}  // namespace rad
