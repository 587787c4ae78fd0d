#include "render/view_path_inputs.h"

#include "device/element_records.h"
#include "render/renderer.h"
#include "render/view_pass.h"
#include "shared_math.h"
#include "util/error.h"
#include "util/sample_streams.h"

namespace rad {
namespace {

std::vector<rad_float4> float4s(const std::vector<glm::vec3>& values) {
    std::vector<rad_float4> out(values.size());
    for (std::size_t i = 0; i < values.size(); ++i) out[i] = {{values[i].x, values[i].y, values[i].z, 0.0f}};
    return out;
}

// The solution's indirect irradiance per element (element_indirect in kernels/view_pass.cl).
std::vector<glm::vec3> indirectPerElement(const PreparedScene& scene, const ViewPathSolution& solution,
                                          const ViewSolutionArgs& arguments, std::uint32_t rays, std::uint32_t seed) {
    const std::size_t count = solution.elements.elements().size();
    std::vector<glm::vec3> perElement(count, glm::vec3(0.0f));
    if (count == 0) return perElement;
    ComputeContext& compute = scene.compute();
    const std::string what = "solution's indirect light over " + std::to_string(count) + " elements";
    const DeviceArray<DirectLightElement> layout = DeviceArray<DirectLightElement>::upload(
        compute, directLightElements(scene.mesh(), solution.elements), what + ": elements");
    const DeviceArray<rad_float4> result =
        DeviceArray<rad_float4>::allocate(compute, count, what, DeviceAccess::write);
    DeviceKernel<ElementIndirectArgs> kernel =
        scene.device().kernel<ElementIndirectArgs>("view_pass.cl", "element_indirect", arguments);
    ElementIndirectArgs args;
    args.layout = layout;
    args.rays = rays;
    args.seed = rad_hash2(seed, kViewIndirectStream);
    args.out = result;
    launchOverElements(kernel, args, count, rays);
    const std::vector<rad_float4> values = result.read();
    for (std::size_t e = 0; e < count; ++e) perElement[e] = {values[e].s[0], values[e].s[1], values[e].s[2]};
    return perElement;
}

}  // namespace

rad_uint viewPathMode(RenderMode mode) {
    return mode == RenderMode::direct ? 1u : 2u;
}

ViewPathInputs::ViewPathInputs(const PreparedScene& scene, const ViewPathSolution& solution, bool direct,
                               std::uint32_t indirectRaysPerElement, std::uint32_t seed)
    : direct_(direct) {
    const std::size_t elementCount = solution.elements.elements().size();
    if (solution.elementIrradiance.size() != elementCount)
        throw InputError("the irradiance is given at " + std::to_string(solution.elementIrradiance.size()) +
                         " elements, the mesh has " + std::to_string(elementCount));
    if (!solution.vertexCaustic.empty() && solution.vertexCaustic.size() != solution.vertices.positions.size())
        throw InputError("the caustic light is given at " + std::to_string(solution.vertexCaustic.size()) +
                         " vertices, the mesh has " + std::to_string(solution.vertices.positions.size()));
    ComputeContext& compute = scene.compute();
    corners_ = DeviceArray<rad_uint4>::upload(compute, elementCorners(solution.vertices), "element corners");
    irradiance_ = DeviceArray<rad_float4>::upload(compute, float4s(solution.elementIrradiance), "element irradiance");
    caustic_ =
        DeviceArray<rad_float4>::upload(compute, float4s(solution.vertexCaustic), "vertex caustic irradiance");
    // Until the indirect light is gathered, a placeholder (element_indirect does not read it).
    indirect_ = DeviceArray<rad_float4>::upload(compute, {}, "vertex indirect irradiance");
    arguments_.elements = solution.deviceElements.nodes;
    arguments_.corners = corners_;
    arguments_.elementIrradiance = irradiance_;
    arguments_.vertexIndirect = indirect_;
    arguments_.vertexCaustic = caustic_;
    arguments_.caustics = solution.vertexCaustic.empty() ? 0 : 1;
    if (!direct) return;
    const std::vector<glm::vec3> perElement =
        indirectPerElement(scene, solution, arguments_, indirectRaysPerElement, seed);
    indirect_ = DeviceArray<rad_float4>::upload(
        compute, float4s(vertexValues(solution.elements, solution.vertices, perElement)), "vertex indirect irradiance");
    arguments_.vertexIndirect = indirect_;
}

}  // namespace rad
