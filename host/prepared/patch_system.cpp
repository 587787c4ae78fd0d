#include "prepared/patch_system.h"

#include "mesh/patch_textures.h"
#include "scene/material_model.h"
#include "scene/surface_kinds.h"

namespace rad {

std::vector<glm::vec3> PatchSystem::exitance() const {
    std::vector<glm::vec3> out(size());
    for (std::size_t p = 0; p < size(); ++p) out[p] = exitance(p);
    return out;
}

PatchSystem buildPatchSystem(const Scene& scene, const Mesh& mesh, const PatchTextureMeans& textures,
                             const Emitters& emitters) {
    PatchSystem system;
    system.area.reserve(mesh.patches.size());
    system.reflectance.reserve(mesh.patches.size());
    system.shadingColour.reserve(mesh.patches.size());
    for (std::size_t k = 0; k < mesh.patches.size(); ++k) {
        const Patch& p = mesh.patches[k];
        system.area.push_back(p.area);
        const Material& m = scene.materials[static_cast<std::size_t>(p.material)];
        // a patch's reflectance by the textures' means over it (roughness enters the layer's
        // albedo unevenly: a texture whose roughness varies within a patch is averaged first)
        const SurfaceLayer layer = surfaceLayer(m, textures.baseColor[k], textures.metalRoughness[k], textures.specular[k]);
        if (layer.present) {
            system.reflectance.push_back(layer.diffuse * layer.diffuseKept + layer.layerAlbedo);
            system.shadingColour.push_back(m.baseColor * textures.baseColor[k]);
        } else {
            system.reflectance.push_back(m.reflectance * textures.baseColor[k]);
            system.shadingColour.push_back(system.reflectance.back());
        }
    }
    system.emission.assign(mesh.patches.size(), glm::vec3(0.0f));
    for (const auto& emitter : emitters.list()) emitter->addPatchEmission(system.emission);
    return system;
}

std::vector<glm::vec3> reflectanceBesideSpecular(const PatchSystem& patches, const Scene& scene, const Mesh& mesh) {
    std::vector<glm::vec3> rho = patches.reflectance;
    for (const Face& face : mesh.faces) {
        if (!surfaceKindOf(scene.materials.at(static_cast<std::size_t>(face.material)))) continue;
        const std::uint32_t cells = face.subdivision * face.subdivision;
        for (const std::uint32_t first : {face.frontPatch, face.backPatch})
            if (first != kNoPatch)
                for (std::uint32_t k = 0; k < cells; ++k) rho.at(first + k) = glm::vec3(0.0f);
    }
    return rho;
}

}  // namespace rad
