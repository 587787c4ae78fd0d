#include "prepared/specular_faces.h"

#include "scene/material_model.h"

namespace rad {

SpecularFaceTable buildSpecularFaces(const Scene& scene, const Mesh& mesh,
                                     const std::vector<glm::vec3>* patchReflectance) {
    SpecularFaceTable out;
    std::vector<SpecularFace> specular(mesh.faces.size());
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        const Face& face = mesh.faces[f];
        const Material& m = scene.materials.at(static_cast<std::size_t>(face.material));
        const SpecularKind kind = specularKind(m);
        if (kind == SpecularKind::none) continue;
        out.any = true;
        SpecularFace& s = specular[f];
        s.kind = kind == SpecularKind::mirror   ? RAD_SPECULAR_MIRROR
                 : kind == SpecularKind::glossy ? RAD_SPECULAR_GLOSSY
                 : m.thickness > 0.0f           ? RAD_SPECULAR_GLASS
                                                : RAD_SPECULAR_THIN_GLASS;
        glm::vec3 colour = m.baseColor;
        const bool metal = kind == SpecularKind::mirror || kind == SpecularKind::glossy;
        const std::uint32_t first = face.frontPatch != kNoPatch ? face.frontPatch : face.backPatch;
        if (metal && m.baseColorTexture.present() && patchReflectance && first != kNoPatch) {
            // the patches' reflectance is baseColor x the texture's mean x this mix (material_model.h)
            const float mix = (1.0f - m.metallic) * (1.0f - m.transmission) + m.metallic;
            const std::uint32_t cells = face.subdivision * face.subdivision;
            glm::vec3 sum(0.0f);
            for (std::uint32_t k = 0; k < cells; ++k) sum += patchReflectance->at(first + k);
            colour = sum / (static_cast<float>(cells) * mix);
        }
        for (int c = 0; c < 3; ++c) s.colour[c] = colour[c];
        s.colour[3] = kind == SpecularKind::glossy ? m.roughness * m.roughness : m.ior > 0.0f ? m.ior : 1.5f;
        for (int k = 0; k < 3; ++k) {
            const glm::vec3 n = face.smooth() ? face.shadingNormals[k] : face.normal;
            for (int c = 0; c < 3; ++c) s.normals[k][c] = n[c];
        }
    }
    if (out.any)
        out.faces = std::move(specular);
    else
        out.faces.resize(1);
    return out;
}

std::vector<glm::vec3> reflectanceBesideSpecular(const PatchSystem& patches, const Scene& scene, const Mesh& mesh) {
    std::vector<glm::vec3> rho = patches.reflectance;
    for (const Face& face : mesh.faces) {
        if (specularKind(scene.materials.at(static_cast<std::size_t>(face.material))) == SpecularKind::none) continue;
        const std::uint32_t cells = face.subdivision * face.subdivision;
        for (const std::uint32_t first : {face.frontPatch, face.backPatch})
            if (first != kNoPatch)
                for (std::uint32_t k = 0; k < cells; ++k) rho.at(first + k) = glm::vec3(0.0f);
    }
    return rho;
}

}  // namespace rad
