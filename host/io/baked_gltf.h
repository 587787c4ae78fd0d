#pragma once
// The lit scene as a binary glTF: every surface side as a mesh of its elements, with the
// radiance (B / pi, linear, W / m^2 / sr) at each vertex in COLOR_0 and an unlit material
// (KHR_materials_unlit), so a glTF viewer shows the baked light. Radiance is not clamped:
// emitters exceed 1, and viewers clip them to white.
//
// Faces whose material has a base colour texture (and emits nothing) keep it: their own unlit
// material shows the texture, with the light in COLOR_0 as rho H / pi (rho the material's
// factor, H the light arriving at the vertex), so a viewer shows rho(uv) H / pi at texel
// resolution, as the camera pass does. Their vertices carry TEXCOORD_0 (with any
// KHR_texture_transform applied), split where a texture seam runs through a welded vertex;
// the image, its sampler and the alpha mask come along.

#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "mesh/elements.h"
#include "mesh/mesh.h"
#include "mesh/vertices.h"

namespace rad {

// `origin`: where the mesh's coordinates are relative to (Scene::origin); the file puts the
// surfaces under one root node translated there, so they sit where the scene had them.
// Elements with T-vertices on their edges are split into a fan around their centroid, so the
// triangles meet without cracks.
// What keeping the textures needs: the scene (materials, images, texture coordinates) and the
// light arriving at each welded vertex (W / m^2).
struct BakedTextures {
    const Scene& scene;
    const std::vector<glm::vec3>& vertexIrradiance;
};

void writeBakedGltf(const std::string& path, const Mesh& mesh, const ElementMesh& elements,
                    const MeshVertices& vertices, const std::vector<glm::vec3>& vertexRadiance,
                    const glm::dvec3& origin, const BakedTextures* textures = nullptr);

}  // namespace rad
