#include "device/device_textures.h"

#include "mesh/patch_textures.h"
#include "scene/material_model.h"
#include "scene/texture_sampling.h"

namespace rad {
namespace {

rad_uint wrapFlag(TextureRef::Wrap wrap) {
    return wrap == TextureRef::Wrap::ClampToEdge      ? RAD_WRAP_CLAMP
           : wrap == TextureRef::Wrap::MirroredRepeat ? RAD_WRAP_MIRROR
                                                      : RAD_WRAP_REPEAT;
}

}  // namespace

TextureTable buildTextureTable(const Scene& scene, const Mesh& mesh) {
    TextureTable t;
    std::vector<rad_uint> imageOffset;
    for (const TextureImage& image : scene.images) {
        imageOffset.push_back(static_cast<rad_uint>(t.texels.size()));
        for (std::size_t k = 0; k + 3 < image.rgba.size(); k += 4)
            t.texels.push_back(image.rgba[k] | (rad_uint{image.rgba[k + 1]} << 8) |
                               (rad_uint{image.rgba[k + 2]} << 16) | (rad_uint{image.rgba[k + 3]} << 24));
    }
    auto slot = [&](const TextureRef& ref) -> rad_int {
        if (!ref.present()) return -1;
        const TextureImage& image = scene.images[static_cast<std::size_t>(ref.image)];
        TextureSlot s{};
        s.offset = imageOffset[static_cast<std::size_t>(ref.image)];
        s.width = static_cast<rad_uint>(image.width);
        s.height = static_cast<rad_uint>(image.height);
        s.flags = wrapFlag(ref.wrapS) | (wrapFlag(ref.wrapT) << 2) | (ref.nearest ? 16u : 0u) | (ref.linear ? 32u : 0u);
        for (int r = 0; r < 2; ++r)
            for (int c = 0; c < 3; ++c) s.rows[r][c] = ref.transform[c][r];
        t.slots.push_back(s);
        return static_cast<rad_int>(t.slots.size() - 1);
    };
    for (const Material& m : scene.materials) {
        t.baseSlot.push_back(slot(m.baseColorTexture));
        t.emissiveSlot.push_back(slot(m.emissiveTexture));
        t.metalSlot.push_back(slot(m.metallicRoughnessTexture));
        t.specularSlot.push_back(slot(m.specularTexture));
        t.specularColorSlot.push_back(slot(m.specularColorTexture));
        t.normalSlot.push_back(slot(m.normalTexture));
    }
    t.alpha.assign(1, AlphaFace{});
    t.faceAlpha.assign(mesh.faces.size(), 0);
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        const Face& face = mesh.faces[f];
        const Material& m = scene.materials[static_cast<std::size_t>(face.material)];
        if (m.alphaMode != Material::AlphaMode::Mask) continue;
        AlphaFace a{};
        a.slot = t.baseSlot[static_cast<std::size_t>(face.material)];
        a.factor = m.alpha;
        a.cutoff = m.alphaCutoff;
        const Surface& surface = scene.surfaces[face.sceneSurface];
        const double corner[3][2] = {{0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}};
        for (int k = 0; k < 3; ++k) {
            const glm::vec2 uv =
                texCoordAt(surface, face.sceneTriangle, m.baseColorTexture.texCoord, corner[k][0], corner[k][1]);
            a.uv[2 * k] = uv.x;
            a.uv[2 * k + 1] = uv.y;
        }
        t.faceAlpha[f] = static_cast<rad_uint>(t.alpha.size());
        t.alpha.push_back(a);
    }
    t.alpha[0].count = static_cast<rad_uint>(t.alpha.size() - 1);
    t.faceTextures.resize(mesh.faces.size());
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        const Face& face = mesh.faces[f];
        const auto m = static_cast<std::size_t>(face.material);
        const Material& material = scene.materials[m];
        FaceTexture& out = t.faceTextures[f];
        out.baseSlot = t.baseSlot[m];
        out.emissiveSlot = t.emissiveSlot[m];
        const Surface& surface = scene.surfaces[face.sceneSurface];
        out.coloured = surface.colors.empty() ? 0u : 1u;
        if (out.baseSlot < 0 && out.emissiveSlot < 0 && out.coloured == 0u) continue;
        t.textured = true;
        if (out.coloured != 0u)
            for (int k = 0; k < 3; ++k) {
                const glm::vec3& colour = surface.colors[surface.triangles[face.sceneTriangle][static_cast<std::size_t>(k)]];
                for (int c = 0; c < 3; ++c) out.colours[4 * k + c] = colour[c];
            }
        const double corner[3][2] = {{0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}};
        for (int k = 0; k < 3; ++k) {
            const glm::vec2 base =
                texCoordAt(surface, face.sceneTriangle, material.baseColorTexture.texCoord, corner[k][0], corner[k][1]);
            const glm::vec2 emissive =
                texCoordAt(surface, face.sceneTriangle, material.emissiveTexture.texCoord, corner[k][0], corner[k][1]);
            out.baseUv[2 * k] = base.x;
            out.baseUv[2 * k + 1] = base.y;
            out.emissiveUv[2 * k] = emissive.x;
            out.emissiveUv[2 * k + 1] = emissive.y;
        }
        // the texture multiplies the reflectance, or under a specular layer the base colour
        const glm::vec3 reflectance = surfaceLayer(material).present ? material.baseColor : material.reflectance;
        for (int c = 0; c < 3; ++c) {
            out.reflectance[c] = reflectance[c];
            out.emission[c] = material.emission[c];
        }
    }
    if (!t.textured) t.faceTextures.assign(1, FaceTexture{});
    // OpenCL buffers may not be empty.
    if (t.texels.empty()) t.texels.push_back(0);
    if (t.slots.empty()) t.slots.push_back(TextureSlot{});
    return t;
}

std::vector<float> srgbTable() {
    std::vector<float> table(256);
    for (int i = 0; i < 256; ++i) table[static_cast<std::size_t>(i)] = srgbToLinear(static_cast<std::uint8_t>(i));
    return table;
}

}  // namespace rad
