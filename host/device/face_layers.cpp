#include "device/face_layers.h"

#include "mesh/patch_textures.h"
#include "scene/ggx_albedo.h"
#include "scene/material_model.h"

namespace rad {

static_assert(kAlbedoCosines == RAD_ALBEDO_COSINES && kAlbedoRoughness == RAD_ALBEDO_ROUGHNESS,
              "the albedo table's size must match the kernels' (kernels/shared_types.h)");

FaceLayerTable buildFaceLayers(const Scene& scene, const Mesh& mesh, const TextureTable& textures) {
    FaceLayerTable out;
    std::vector<SurfaceLayer> layers;
    layers.reserve(scene.materials.size());
    for (const Material& m : scene.materials) layers.push_back(surfaceLayer(m));
    std::vector<FaceLayer> faces(mesh.faces.size());
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        const Face& face = mesh.faces[f];
        const auto index = static_cast<std::size_t>(face.material);
        const SurfaceLayer& l = layers.at(index);
        if (!l.present) continue;
        out.any = true;
        const Material& m = scene.materials[index];
        FaceLayer& d = faces[f];
        for (int k = 0; k < 3; ++k) {
            const glm::vec3 n = face.smooth() ? face.shadingNormals[k] : face.normal;
            for (int c = 0; c < 3; ++c) d.normals[k][c] = n[c];
        }
        for (int c = 0; c < 3; ++c) d.dielectric[c] = l.dielectricF0[c];
        d.dielectric[3] = l.dielectricF90;
        // a metallicRoughnessTexture that could not be read: the metal's part diffuse, as
        // surfaceLayer has it
        const bool unread = m.metallicRoughnessTextured && !m.metallicRoughnessTexture.present();
        d.factors[0] = unread ? 0.0f : m.metallic;
        d.factors[1] = m.roughness;
        d.factors[2] = unread ? (1.0f - m.metallic) * (1.0f - m.transmission) + m.metallic : 1.0f - m.transmission;
        d.factors[3] = 1.0f;
        const Surface& surface = scene.surfaces[face.sceneSurface];
        // a texture's coordinates at the face's corners, in its set
        const auto cornerUvs = [&](const TextureRef& ref, float* out) {
            const double corner[3][2] = {{0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}};
            for (int k = 0; k < 3; ++k) {
                const glm::vec2 uv = texCoordAt(surface, face.sceneTriangle, ref.texCoord, corner[k][0], corner[k][1]);
                out[2 * k] = uv.x;
                out[2 * k + 1] = uv.y;
            }
        };
        d.metalSlot = textures.metalSlot.at(index);
        if (d.metalSlot >= 0) cornerUvs(m.metallicRoughnessTexture, d.metalUv);
        // KHR_materials_specular's textures: the kernels make the dielectric's F0 and F90 per
        // texel from the factors (surfaceLayer's, before the textures)
        d.specularTextures = -1;
        const rad_int strengthSlot = textures.specularSlot.at(index), colourSlot = textures.specularColorSlot.at(index);
        if (strengthSlot >= 0 || colourSlot >= 0) {
            FaceSpecularTextures t{};
            for (int c = 0; c < 3; ++c) t.specular[c] = iorReflectance(m) * m.specularColor[c];
            t.specular[3] = m.specular;
            t.strengthSlot = strengthSlot;
            t.colourSlot = colourSlot;
            if (strengthSlot >= 0) cornerUvs(m.specularTexture, t.strengthUv);
            if (colourSlot >= 0) cornerUvs(m.specularColorTexture, t.colourUv);
            d.specularTextures = static_cast<rad_int>(out.specularTextures.size());
            out.specularTextures.push_back(t);
        }
    }
    if (out.specularTextures.empty()) out.specularTextures.resize(1);
    if (out.any) {
        out.faces = std::move(faces);
    } else {
        out.faces.resize(1);
    }
    return out;
}

}  // namespace rad
