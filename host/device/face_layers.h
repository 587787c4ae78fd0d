#pragma once
// Which faces have glTF's specular layer over their diffuse colour (scene/material_model.h:
// SurfaceLayer), as the kernels read them (FaceLayer, kernels/material.h); they look the layer's
// albedo up in scene/ggx_albedo.h's table (DeviceScene uploads it). Read by the camera pass, the lightmap's
// texels and the path tracer; the radiosity pass takes the layer's share in the patches'
// reflectance instead (prepared/patch_system.h).

#include <vector>

#include "device/device_textures.h"
#include "mesh/mesh.h"
#include "scene/scene.h"
#include "shared_types.h"

namespace rad {

struct FaceLayerTable {
    std::vector<FaceLayer> faces;  // per face where any face has a layer, else one entry
    bool any = false;
    // the layered faces' KHR_materials_specular textures (FaceLayer::specularTextures), or one entry
    std::vector<FaceSpecularTextures> specularTextures;
};

// `textures`: the scene's texture slots (the metallicRoughnessTextures' among them).
FaceLayerTable buildFaceLayers(const Scene& scene, const Mesh& mesh, const TextureTable& textures);

}  // namespace rad
