#pragma once
// Running kernels/direct_light.cl over a solve's elements: the elements laid out as its kernels
// read them, and the launches. Shared by the emitters that deliver direct light (punctual
// lights, the sky).

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "cl/opencl.h"
#include "light/emitter.h"
#include "mesh/elements.h"
#include "prepared/prepared_scene.h"

namespace rad {

// Per element, kDirectLightElementStride float4s: its three corners (w of the first: 1 when its
// back is black, 0 when the back has patches of its own); its unit normal (w: how far ray
// origins are lifted off the surface, as the patch's rays are, mesh/sampling_tables.h); the
// corners' barycentric weights in their face (b1, b2 of corners 0 and 1, then of corner 2) and
// the face's index (its bits in the last float4's z), for the face's alpha mask.
inline constexpr std::size_t kDirectLightElementStride = 6;
std::vector<cl_float4> directLightElements(const Mesh& mesh, const ElementMesh& elements);

// Uploads `elements` (directLightElements), binds them with the scene's buffers as the kernel's
// first arguments followed by (first, count), calls `bind` to set the arguments after those, and
// launches the kernel over all elements in launches of about `raysPerLaunch` rays
// (`raysPerElement` each). `what` names the work in device errors.
// Takes a direct-light kernel's result into `light`: per element e, out[stride e] is the mean
// irradiance on its front and out[stride e + 1] on its black back (W / m^2, rgb), each times
// `scale` per channel; with stride 3, out[3e + 2] is the part of the front's that came by way of
// mirrors or glass (sky_direct, environment_direct). Adds the power that arrived at each
// element, what the backs absorbed, and as escaped what of `power` neither received (what glass
// absorbed on the way included). Sums in element order, so they depend on nothing but the
// elements.
void addFrontsAndBacks(const ElementMesh& elements, const std::vector<cl_float4>& out, std::size_t stride,
                       const glm::dvec3& scale, const glm::dvec3& power, DirectLight& light);

// `programFile`: the kernel file (direct_light.cl, or view_pass.cl for the camera pass's indirect light).
void launchOverElements(const PreparedScene& scene, const std::string& programFile, const std::string& kernelName,
                        const std::vector<cl_float4>& elements, double raysPerElement, const std::string& what,
                        const std::function<void(cl::Kernel&, cl_uint nextArgument)>& bind,
                        SpecularModel model = SpecularModel::follow);

}  // namespace rad
