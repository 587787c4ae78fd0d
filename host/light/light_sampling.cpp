#include "light/light_sampling.h"

#include "light/emitter.h"
#include "mesh/mesh.h"
#include "scene/scene.h"
#include "util/shares.h"

namespace rad {

SurfaceLightTable surfaceLightTable(const Scene& scene, const Mesh& mesh, const Emitters& emitters) {
    SurfaceLightTable table;
    std::vector<double> power;
    for (const DirectSource& source : emitters.directSources()) {
        const std::uint32_t face = mesh.patches.at(source.triangle).face;
        const Material& material = scene.materials.at(static_cast<std::size_t>(mesh.faces.at(face).material));
        if (material.emissiveTexture.present()) continue;
        // Alpha-masked: rays pass through its clear texels, which a point drawn on the whole
        // triangle would light from; rays that hit it find its light instead.
        if (material.alphaMode == Material::AlphaMode::Mask) continue;
        const glm::vec3& le = source.radiance;
        const double weight = (static_cast<double>(le.x) + le.y + le.z) * source.area;
        if (!(weight > 0.0)) continue;
        if (table.lightOfPatch.empty()) table.lightOfPatch.assign(mesh.patches.size(), 0);
        SurfaceLight light{};
        light.radiance[0] = le.x;
        light.radiance[1] = le.y;
        light.radiance[2] = le.z;
        light.triangle = source.triangle;
        table.lights.push_back(light);
        table.lightOfPatch[source.triangle] = static_cast<std::uint32_t>(table.lights.size());
        power.push_back(weight);
    }
    appendShares(power.data(), power.size(), table.ends);
    const std::vector<std::uint32_t> guide = shareGuide(table.ends.data(), table.lights.size());
    table.ends.insert(table.ends.end(), guide.begin(), guide.end());
    return table;
}

}  // namespace rad
