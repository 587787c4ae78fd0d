#include "scene/closed_glass.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <map>
#include <utility>

#include "scene/material_model.h"

namespace rad {
namespace {

// Whether glass material `material`'s triangles in `surface` form closed meshes: their corners
// welded by exact position, each edge shared by exactly two of them. True where it has none.
bool closedWhere(const Surface& surface, int material) {
    std::map<std::array<std::uint32_t, 3>, std::uint32_t> welded;  // a position's bits -> its id
    auto id = [&](std::uint32_t vertex) {
        const glm::vec3 p = surface.positions[vertex] + glm::vec3(0.0f);  // -0 and 0 alike
        std::array<std::uint32_t, 3> bits;
        std::memcpy(bits.data(), &p, sizeof bits);
        return welded.emplace(bits, static_cast<std::uint32_t>(welded.size())).first->second;
    };
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
    for (std::size_t t = 0; t < surface.triangles.size(); ++t) {
        if (surface.triangleMaterial[t] != material) continue;
        const std::array<std::uint32_t, 3> c = {id(surface.triangles[t][0]), id(surface.triangles[t][1]),
                                                id(surface.triangles[t][2])};
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = c[static_cast<std::size_t>(k)], b = c[static_cast<std::size_t>((k + 1) % 3)];
            ++edges[{std::min(a, b), std::max(a, b)}];
        }
    }
    for (const auto& [edge, count] : edges)
        if (count != 2) return false;
    return true;
}

}  // namespace

std::vector<std::string> solidifyClosedGlass(Scene& scene) {
    std::vector<std::string> solid;
    for (std::size_t m = 0; m < scene.materials.size(); ++m) {
        Material& material = scene.materials[m];
        if (specularKind(material) != SpecularKind::glass || material.thickness > 0.0f) continue;
        bool used = false, closed = true;
        for (const Surface& surface : scene.surfaces) {
            bool here = false;
            for (int t : surface.triangleMaterial) here = here || t == static_cast<int>(m);
            if (!here) continue;
            used = true;
            closed = closed && closedWhere(surface, static_cast<int>(m));
        }
        if (!used) continue;
        if (closed) {
            material.thickness = 1.0f;
            solid.push_back(material.name);
        } else {
            scene.warnings.push_back("material '" + material.name +
                                     "': --solid-glass leaves it thin-walled: its mesh is not closed");
        }
    }
    return solid;
}

}  // namespace rad
