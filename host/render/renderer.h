#pragma once
// Renders the radiosity solution from a view with kernels/render.cl.

#include <vector>

#include <glm/vec3.hpp>

#include "cl/kernel_pack.h"
#include "device/device_elements.h"
#include "mesh/vertices.h"
#include "prepared/prepared_scene.h"
#include "render/image.h"
#include "render/view.h"

namespace rad {

struct RenderOptions {
    int width = 512, height = 512;
    int samplesPerSide = 2;  // samplesPerSide^2 stratified samples per pixel
    bool wireframe = false;  // darken pixels near element edges, to show the mesh
};

// Each element's vertices, as the kernels read them (w unused).
std::vector<rad_uint4> elementCorners(const MeshVertices& vertices);

// vertexRadiance: radiance B / pi at each vertex of `vertices` (made from `elements`).
// vertexIrradiance: the light H arriving at each vertex (W / m^2); where it is given, faces
// whose material has a texture show it at pixel resolution, Le(uv) + rho(uv) H / pi
// (README, "Textures"); other faces show vertexRadiance as always.
Image renderView(const PreparedScene& scene, const DeviceElements& elements, const MeshVertices& vertices,
                 const std::vector<glm::vec3>& vertexRadiance, const View& view, const RenderOptions& options,
                 const std::vector<glm::vec3>* vertexIrradiance = nullptr);

}  // namespace rad
