#include "device/face_normal_maps.h"

#include "mesh/patch_textures.h"

namespace rad {

FaceNormalMapTable buildFaceNormalMaps(const Scene& scene, const Mesh& mesh, const TextureTable& textures) {
    FaceNormalMapTable out;
    std::vector<FaceNormalMap> faces(mesh.faces.size());
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        FaceNormalMap& d = faces[f];
        d.slot = -1;
        const Face& face = mesh.faces[f];
        const auto index = static_cast<std::size_t>(face.material);
        const rad_int slot = textures.normalSlot.at(index);
        const Surface& surface = scene.surfaces[face.sceneSurface];
        if (slot < 0 || surface.tangents.empty()) continue;
        const auto& triangle = surface.triangles[face.sceneTriangle];
        bool framed = true;
        for (int k = 0; k < 3; ++k) framed = framed && surface.tangents[triangle[k]].w != 0.0f;
        if (!framed) continue;  // a corner without a frame (a degenerate triangle's): drawn without the map
        const Material& m = scene.materials[index];
        out.any = true;
        d.slot = slot;
        d.scale = m.normalScale;
        const double corner[3][2] = {{0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}};
        for (int k = 0; k < 3; ++k) {
            const glm::vec3 n = face.smooth() ? face.shadingNormals[k] : face.normal;
            const glm::vec4 t = surface.tangents[triangle[k]];
            for (int c = 0; c < 3; ++c) {
                d.normals[k][c] = n[c];
                d.tangents[k][c] = t[c];
            }
            d.tangents[k][3] = t.w;
            const glm::vec2 uv =
                texCoordAt(surface, face.sceneTriangle, m.normalTexture.texCoord, corner[k][0], corner[k][1]);
            d.uv[2 * k] = uv.x;
            d.uv[2 * k + 1] = uv.y;
        }
    }
    if (!out.any) {  // one entry, no map
        FaceNormalMap none{};
        none.slot = -1;
        faces.assign(1, none);
    }
    out.faces = std::move(faces);
    return out;
}

}  // namespace rad
