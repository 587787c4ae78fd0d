#include "device/face_layers.h"

#include "scene/ggx_albedo.h"
#include "scene/material_model.h"

namespace rad {

static_assert(kAlbedoCosines == RAD_ALBEDO_COSINES && kAlbedoRoughness == RAD_ALBEDO_ROUGHNESS,
              "the albedo table's size must match the kernels' (kernels/shared_types.h)");

FaceLayerTable buildFaceLayers(const Scene& scene, const Mesh& mesh) {
    FaceLayerTable out;
    std::vector<SurfaceLayer> layers;
    layers.reserve(scene.materials.size());
    for (const Material& m : scene.materials) layers.push_back(surfaceLayer(m));
    std::vector<FaceLayer> faces(mesh.faces.size());
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        const Face& face = mesh.faces[f];
        const SurfaceLayer& l = layers.at(static_cast<std::size_t>(face.material));
        if (!l.present) continue;
        out.any = true;
        FaceLayer& d = faces[f];
        for (int k = 0; k < 3; ++k) {
            const glm::vec3 n = face.smooth() ? face.shadingNormals[k] : face.normal;
            for (int c = 0; c < 3; ++c) d.normals[k][c] = n[c];
        }
        for (int c = 0; c < 3; ++c) {
            d.f0[c] = l.f0[c];
            d.dielectric[c] = l.dielectricF0[c];
            d.diffuseKept[c] = l.diffuseKept[c];
            d.layerAlbedo[c] = l.layerAlbedo[c];
        }
        d.f0[3] = l.f90;
        d.dielectric[3] = l.dielectricF90;
        d.diffuseKept[3] = l.roughness;
    }
    if (out.any) {
        out.faces = std::move(faces);
        out.albedo = ggxAlbedoTable().values;
    } else {
        out.faces.resize(1);
        out.albedo.assign(1, 0.0f);
    }
    return out;
}

}  // namespace rad
