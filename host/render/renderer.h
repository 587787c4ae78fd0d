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
    int samples = 4;  // per pixel, stratified over pixelGrid(samples)
    bool wireframe = false;  // darken pixels near element edges, to show the mesh
};

// The grid a pixel's samples are stratified over: `across` columns by `down` rows, across * down
// = samples, as square as the count allows: `down` is the largest divisor of samples not above
// its square root. A square count n^2 gives the n x n grid; 8 gives 4 x 2; a prime p gives one
// row of p columns (still one sample per cell, stratified across only).
struct PixelGrid {
    int across = 1, down = 1;
};
PixelGrid pixelGrid(int samples);

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
