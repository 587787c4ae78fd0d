#include "render/face_materials.h"

#include <algorithm>
#include <cmath>

#include "cl/buffers.h"
#include "scene/material_model.h"

static_assert(sizeof(SpecularFace) == 80, "SpecularFace must match the kernels' layout");

namespace rad {

FaceMaterialArrays faceMaterialArrays(const PreparedScene& scene) {
    const Mesh& mesh = scene.mesh();
    const PatchSystem& patches = scene.patches();
    FaceMaterialArrays out;
    out.reflectance.resize(std::max<std::size_t>(mesh.faces.size(), 1));
    out.emission.resize(out.reflectance.size());
    float largest = 0.0f;
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        out.reflectance[f] = float4Of(patches.reflectance[mesh.faces[f].frontPatch]);
        out.emission[f] = float4Of(patches.emission[mesh.faces[f].frontPatch]);
        for (const glm::vec3& p : mesh.faces[f].p)
            largest = std::max({largest, std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
    }
    out.lift = largest * 0x1p-18f;
    const std::vector<Material>& materials = scene.scene().materials;
    std::vector<SpecularFace> specular(mesh.faces.size());
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        const Face& face = mesh.faces[f];
        const Material& m = materials.at(static_cast<std::size_t>(face.material));
        const SpecularKind kind = specularKind(m);
        if (kind == SpecularKind::none) continue;
        out.anySpecular = true;
        SpecularFace& s = specular[f];
        s.kind = kind == SpecularKind::mirror ? RAD_SPECULAR_MIRROR
                 : m.thickness > 0.0f         ? RAD_SPECULAR_GLASS
                                              : RAD_SPECULAR_THIN_GLASS;
        for (int c = 0; c < 3; ++c) s.colour[c] = m.baseColor[c];
        s.colour[3] = m.ior > 0.0f ? m.ior : 1.5f;
        for (int k = 0; k < 3; ++k) {
            const glm::vec3 n = face.smooth() ? face.shadingNormals[k] : face.normal;
            for (int c = 0; c < 3; ++c) s.normals[k][c] = n[c];
        }
    }
    if (out.anySpecular)
        out.specular = std::move(specular);
    else
        out.specular.resize(1);
    return out;
}

}  // namespace rad
