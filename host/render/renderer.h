#pragma once
// Renders the radiosity solution from a view with kernels/render.cl.

#include <vector>

#include <glm/vec3.hpp>

#include "cl/compute_context.h"
#include "cl/device_scene.h"
#include "mesh/vertices.h"
#include "render/image.h"
#include "render/view.h"

namespace rad {

struct RenderOptions {
    int width = 512, height = 512;
    int samplesPerSide = 2;  // samplesPerSide^2 stratified samples per pixel
};

// vertexRadiance: radiance B / pi at each vertex of `vertices`.
Image renderView(ComputeContext& compute, const DeviceScene& scene, const MeshVertices& vertices,
                 const std::vector<glm::vec3>& vertexRadiance, const View& view, const RenderOptions& options);

}  // namespace rad
