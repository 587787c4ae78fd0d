#pragma once
// Elements as the kernels that compute light over elements read them (DirectLightElement:
// kernels/direct_light.cl, and the camera pass's indirect light per element,
// kernels/view_pass.cl's element_indirect), and the launches over them.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "cl/kernel_pack.h"
#include "mesh/elements.h"
#include "mesh/mesh.h"
#include "shared_types.h"

namespace rad {

// Per element: its corners, its patch's unit normal and how far ray origins are lifted off it (as
// the patch's rays are, mesh/sampling_tables.h), the corners' barycentric weights in their face
// and the face (for its alpha mask), and whether its back is black.
std::vector<DirectLightElement> directLightElements(const Mesh& mesh, const ElementMesh& elements);

// Runs `kernel` over `count` elements in launches of about 2^22 rays (`raysPerElement` each):
// seconds at most on a CPU, far from a GPU's watchdog. Sets args.first and args.elementCount.
template <typename Args>
void launchOverElements(DeviceKernel<Args>& kernel, Args& args, std::size_t count, double raysPerElement) {
    const double perLaunch = std::max(1.0, std::floor(4194304.0 / std::max(raysPerElement, 1.0)));
    const auto step = static_cast<std::size_t>(std::min(perLaunch, 1048576.0));
    args.elementCount = static_cast<rad_uint>(count);
    for (std::size_t first = 0; first < count; first += step) {
        args.first = static_cast<rad_uint>(first);
        kernel.launch(args, std::min(step, count - first));
    }
}

}  // namespace rad
