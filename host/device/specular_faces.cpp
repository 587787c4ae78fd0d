#include "device/specular_faces.h"

#include <algorithm>
#include <cmath>

#include "scene/surface_kinds.h"

namespace rad {

SpecularFaceTable buildSpecularFaces(const Scene& scene, const Mesh& mesh,
                                     const std::vector<glm::vec3>* patchReflectance) {
    SpecularFaceTable out;
    std::vector<SpecularFace> specular(mesh.faces.size());
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        const Face& face = mesh.faces[f];
        const Material& m = scene.materials.at(static_cast<std::size_t>(face.material));
        const SurfaceKind* kind = surfaceKindOf(m);
        if (!kind) continue;
        out.any = true;
        SpecularFace& s = specular[f];
        s.kind = kind->id;
        s.alpha = kind->alpha ? kind->alpha(m) : 0.0f;
        if (s.kind == RAD_SPECULAR_GLOSSY) out.glossy = true;
        if (s.kind == RAD_SPECULAR_GLASS && m.attenuationDistance > 0.0f)  // Beer-Lambert inside the solid
            for (int c = 0; c < 3; ++c)
                s.attenuation[c] = -std::log(std::max(m.attenuationColor[c], 1e-30f)) / m.attenuationDistance;
        glm::vec4 colour = kind->describe(m);
        const std::uint32_t first = face.frontPatch != kNoPatch ? face.frontPatch : face.backPatch;
        const bool coloured = m.baseColorTexture.present() || !scene.surfaces[face.sceneSurface].colors.empty();
        if (kind->textureColour && coloured && patchReflectance && first != kNoPatch) {
            // the patches' reflectance is baseColor x the texture's and vertex colours' mean x this mix
            // (material_model.h)
            const float mix = (1.0f - m.metallic) * (1.0f - m.transmission) + m.metallic;
            const std::uint32_t cells = face.subdivision * face.subdivision;
            glm::vec3 sum(0.0f);
            for (std::uint32_t k = 0; k < cells; ++k) sum += patchReflectance->at(first + k);
            const glm::vec3 mean = sum / (static_cast<float>(cells) * mix);
            colour = glm::vec4(mean, colour.w);
        }
        for (int c = 0; c < 4; ++c) s.colour[c] = colour[c];
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

}  // namespace rad
