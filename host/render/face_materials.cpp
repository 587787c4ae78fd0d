#include "render/face_materials.h"

#include <algorithm>

#include "cl/buffers.h"

namespace rad {

FaceMaterialArrays faceMaterialArrays(const PreparedScene& scene) {
    const Mesh& mesh = scene.mesh();
    const PatchSystem& patches = scene.patches();
    FaceMaterialArrays out;
    out.reflectance.resize(std::max<std::size_t>(mesh.faces.size(), 1));
    out.emission.resize(out.reflectance.size());
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        out.reflectance[f] = float4Of(patches.reflectance[mesh.faces[f].frontPatch]);
        out.emission[f] = float4Of(patches.emission[mesh.faces[f].frontPatch]);
    }
    return out;
}

}  // namespace rad
