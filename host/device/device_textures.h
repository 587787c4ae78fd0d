#pragma once
// The scene's textures as the kernels read them (kernels/texture.h): every image's texels in one
// buffer, a TextureSlot for each material's base colour and emissive texture, and the
// alpha-masked faces (AlphaFace) the traversal lets rays through. Built once, uploaded with the
// scene (device/device_scene.h).

#include <cstdint>
#include <vector>

#include "mesh/mesh.h"
#include "scene/scene.h"
#include "shared_types.h"

namespace rad {

struct TextureTable {
    std::vector<rad_uint> texels;  // RGBA8, R in the lowest byte
    std::vector<TextureSlot> slots;
    std::vector<rad_int> baseSlot;      // per material: its base colour texture's slot, or -1
    std::vector<rad_int> emissiveSlot;  // per material: its emissive texture's slot, or -1
    std::vector<rad_int> metalSlot;     // per material: its metallicRoughnessTexture's slot, or -1
    std::vector<rad_int> specularSlot;       // its KHR_materials_specular specularTexture's, or -1
    std::vector<rad_int> specularColorSlot;  // and specularColorTexture's
    std::vector<rad_int> normalSlot;    // per material: its normalTexture's slot, or -1
    std::vector<AlphaFace> alpha;       // [0]: the header (count); then one per masked face
    std::vector<rad_uint> faceAlpha;    // per face: its entry in `alpha`, or 0
    // Per face: its textures' coordinates and factors (kernels/render.cl, pathtrace.cl); one
    // entry only when no face is textured (`textured` false).
    std::vector<FaceTexture> faceTextures;
    bool textured = false;
};

// The sRGB decoding table the kernels read texels through (scene/texture_sampling.h).
std::vector<float> srgbTable();

TextureTable buildTextureTable(const Scene& scene, const Mesh& mesh);

}  // namespace rad
