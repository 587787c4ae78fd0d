#include "scene/surface_kinds.h"

#include <utility>

#include "scene/material_model.h"

namespace rad {
namespace {

std::vector<SurfaceKind> builtInKinds() {
    auto ior = [](const Material& m) { return m.ior > 0.0f ? m.ior : 1.5f; };
    auto glass = [](const Material& m) { return specularKind(m) == SpecularKind::glass; };
    auto glassAlpha = [](const Material& m) {
        return m.roughness > kSmoothSurface ? m.roughness * m.roughness : 0.0f;
    };
    return {
        {"mirror", RAD_SPECULAR_MIRROR, [](const Material& m) { return specularKind(m) == SpecularKind::mirror; },
         [ior](const Material& m) { return glm::vec4(m.baseColor, ior(m)); }, true},
        {"rough metal", RAD_SPECULAR_GLOSSY, [](const Material& m) { return specularKind(m) == SpecularKind::glossy; },
         [](const Material& m) { return glm::vec4(m.baseColor, m.roughness * m.roughness); }, true},
        {"glass", RAD_SPECULAR_GLASS, [glass](const Material& m) { return glass(m) && m.thickness > 0.0f; },
         [ior](const Material& m) { return glm::vec4(m.baseColor, ior(m)); }, false, glassAlpha},
        {"thin pane", RAD_SPECULAR_THIN_GLASS, [glass](const Material& m) { return glass(m) && !(m.thickness > 0.0f); },
         [ior](const Material& m) { return glm::vec4(m.baseColor, ior(m)); }, false, glassAlpha},
    };
}

std::vector<SurfaceKind>& kinds() {
    static std::vector<SurfaceKind> all = builtInKinds();
    return all;
}

}  // namespace

const std::vector<SurfaceKind>& surfaceKinds() {
    return kinds();
}

void addSurfaceKind(SurfaceKind kind) {
    kinds().push_back(std::move(kind));
}

const SurfaceKind* surfaceKindOf(const Material& material) {
    for (const SurfaceKind& kind : kinds())
        if (kind.takes(material)) return &kind;
    return nullptr;
}

}  // namespace rad
