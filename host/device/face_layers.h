#pragma once
// Which faces have glTF's specular layer over their diffuse colour (scene/material_model.h:
// SurfaceLayer), as the kernels read them (FaceLayer, kernels/material.h), with the table of the
// layer's albedo (scene/ggx_albedo.h) they look up. Read by the camera pass, the lightmap's
// texels and the path tracer; the radiosity pass takes the layer's share in the patches'
// reflectance instead (prepared/patch_system.h).

#include <vector>

#include "mesh/mesh.h"
#include "scene/scene.h"
#include "shared_types.h"

namespace rad {

struct FaceLayerTable {
    std::vector<FaceLayer> faces;  // per face where any face has a layer, else one entry
    std::vector<float> albedo;     // GgxAlbedoTable::values where any face has a layer, else one entry
    bool any = false;
};

FaceLayerTable buildFaceLayers(const Scene& scene, const Mesh& mesh);

}  // namespace rad
