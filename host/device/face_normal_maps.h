#pragma once
// Which faces a normal map shades (glTF's normalTexture), as the kernels read them
// (FaceNormalMap, kernels/material.h: mapped_normal): each corner's normal and tangent frame
// (scene/tangents.h) and texture coordinates, the texture's slot and its scale. Read by the
// camera pass and the path tracer at every face, and by every pass that follows mirrors, glass
// and rough metals; the radiosity pass's diffuse patches keep the geometric normals, as the
// two-pass method has it.

#include <vector>

#include "device/device_textures.h"
#include "mesh/mesh.h"
#include "scene/scene.h"
#include "shared_types.h"

namespace rad {

struct FaceNormalMapTable {
    std::vector<FaceNormalMap> faces;  // per face where any face has a normal map, else one entry
    bool any = false;
};

// `textures`: the scene's texture slots (the normal textures' among them).
FaceNormalMapTable buildFaceNormalMaps(const Scene& scene, const Mesh& mesh, const TextureTable& textures);

}  // namespace rad
