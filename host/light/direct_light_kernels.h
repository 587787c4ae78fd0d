#pragma once
// Kernels that compute light over a solve's elements (kernels/direct_light.cl, and the camera
// pass's indirect light per element, kernels/view_pass.cl's element_indirect): the elements as
// they read them (DirectLightElement), the launches, and the results taken into a DirectLight.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "cl/kernel_pack.h"
#include "light/emitter.h"
#include "prepared/prepared_scene.h"
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

// Takes a direct-light kernel's result into `light`: per element e, out[stride e] is the mean
// irradiance on its front and out[stride e + 1] on its black back (W / m^2, rgb), each times
// `scale` per channel; with stride 3, out[3e + 2] is the part of the front's that came by way of
// mirrors or glass (environment_direct). Adds the power that arrived at each
// element, what the backs absorbed, and as escaped what of `power` neither received (what glass
// absorbed on the way included). Sums in element order, so they depend on nothing but the
// elements.
void addFrontsAndBacks(const ElementMesh& elements, const std::vector<rad_float4>& out, std::size_t stride,
                       const glm::dvec3& scale, const glm::dvec3& power, DirectLight& light);

// The light from outside (the uniform sky or the environment map, DeviceScene's) delivered to the
// elements by kernels/direct_light.cl's environment_direct, `raysPerSide` rays per element side
// keyed by `key`, its result times `scale` (pi L for a uniform sky, whose kernel gives the
// fraction of it each element sees; 1 for a map) taken into `light` (addFrontsAndBacks, with the
// emitter's `power`).
void addEnvironmentDirectLight(const PreparedScene& scene, const ElementMesh& elements, std::uint32_t raysPerSide,
                               std::uint32_t key, SpecularModel model, const glm::dvec3& scale,
                               const glm::dvec3& power, DirectLight& light);

}  // namespace rad
