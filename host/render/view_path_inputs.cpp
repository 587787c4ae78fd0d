#include "render/view_path_inputs.h"

#include <algorithm>

#include "cl/buffers.h"
#include "cl/error.h"
#include "light/direct_light_kernels.h"
#include "prepared/device_textures.h"
#include "render/face_materials.h"
#include "render/view_pass.h"
#include "shared_math.h"
#include "util/error.h"
#include "util/sample_streams.h"

namespace rad {
namespace {

std::vector<cl_float4> float4s(const std::vector<glm::vec3>& values) {
    std::vector<cl_float4> out(std::max<std::size_t>(values.size(), 1));
    for (std::size_t i = 0; i < values.size(); ++i) out[i] = float4Of(values[i]);
    return out;
}

std::vector<cl_uint4> cornerIndices(const MeshVertices& vertices) {
    std::vector<cl_uint4> corners(std::max<std::size_t>(vertices.corners.size(), 1));
    for (std::size_t e = 0; e < vertices.corners.size(); ++e)
        corners[e] = {{vertices.corners[e][0], vertices.corners[e][1], vertices.corners[e][2], 0}};
    return corners;
}

}  // namespace

cl_uint viewPathMode(RenderMode mode) {
    return mode == RenderMode::direct ? 1u : 2u;
}

ViewPathInputs::Bytes ViewPathInputs::deviceBytes(const PreparedScene& scene, const ViewPathSolution& solution,
                                                  RenderMode mode) {
    const std::uint64_t vertexBytes = std::max<std::size_t>(solution.vertexIrradiance.size(), 1) * sizeof(cl_float4);
    const std::uint64_t sizes[] = {std::max<std::size_t>(solution.vertices.corners.size(), 1) * sizeof(cl_uint4),
                                   vertexBytes,
                                   mode == RenderMode::direct ? vertexBytes : sizeof(cl_float4),
                                   solution.vertexCaustic.empty() ? sizeof(cl_float4) : vertexBytes,
                                   std::max<std::size_t>(scene.mesh().faces.size(), 1) * sizeof(cl_float4),
                                   std::max<std::size_t>(scene.mesh().faces.size(), 1) * sizeof(cl_float4),
                                   scene.device().faceTextures.size() * sizeof(FaceTexture)};
    Bytes bytes;
    for (std::uint64_t size : sizes) {
        bytes.total += size;
        bytes.largest = std::max(bytes.largest, size);
    }
    return bytes;
}

ViewPathInputs::ViewPathInputs(const PreparedScene& scene, const ViewPathSolution& solution, RenderMode mode,
                               std::uint32_t indirectRaysPerElement, std::uint32_t seed)
    : deviceElements_(solution.deviceElements) {
    if (mode == RenderMode::radiosity) throw InputError("the radiosity mode reads no paths");
    if (!solution.vertexCaustic.empty() && solution.vertexCaustic.size() != solution.vertexIrradiance.size())
        throw InputError("the caustic light is given at " + std::to_string(solution.vertexCaustic.size()) +
                         " vertices, the irradiance at " + std::to_string(solution.vertexIrradiance.size()));
    ComputeContext& compute = scene.compute();
    const FaceMaterialArrays materials = faceMaterialArrays(scene);
    corners_ = uploadBuffer(compute, cornerIndices(solution.vertices), "element corners");
    irradiance_ = uploadBuffer(compute, float4s(solution.vertexIrradiance), "vertex irradiance");
    reflectance_ = uploadBuffer(compute, materials.reflectance, "faces' reflectances");
    emission_ = uploadBuffer(compute, materials.emission, "faces' emission");
    faceTextures_ = uploadBuffer(compute, scene.device().faceTextures, "faces' texture coordinates");
    srgb_ = uploadBuffer(compute, srgbTable(), "sRGB table");
    textured_ = scene.device().textured ? 1 : 0;
    caustics_ = solution.vertexCaustic.empty() ? 0 : 1;
    caustic_ = uploadBuffer(compute, float4s(solution.vertexCaustic), "vertex caustic irradiance");
    std::vector<glm::vec3> indirect;
    if (mode == RenderMode::direct) {
        // The solution's indirect irradiance per element (element_indirect in kernels/view_pass.cl),
        // then per vertex.
        const std::size_t count = solution.elements.elements().size();
        std::vector<glm::vec3> perElement(count, glm::vec3(0.0f));
        if (count > 0) {
            const std::string what =
                "gathering the solution's indirect light over " + std::to_string(count) + " elements";
            cl::Buffer result = allocateBuffer<cl_float4>(compute, count, what, CL_MEM_WRITE_ONLY);
            launchOverElements(scene, "view_pass.cl", "element_indirect",
                               directLightElements(scene.mesh(), solution.elements), indirectRaysPerElement, what,
                               [&](cl::Kernel& kernel, cl_uint next) {
                                   setKernelArgs(kernel, next, deviceElements_.nodes, corners_, irradiance_,
                                                 reflectance_, emission_, faceTextures_, srgb_, textured_, caustics_,
                                                 static_cast<cl_uint>(indirectRaysPerElement),
                                                 static_cast<cl_uint>(rad_hash2(seed, kViewIndirectStream)), result);
                               });
            try {
                const std::vector<cl_float4> values = readBuffer<cl_float4>(compute, result, count);
                for (std::size_t e = 0; e < count; ++e)
                    perElement[e] = {values[e].s[0], values[e].s[1], values[e].s[2]};
            } catch (const cl::Error& e) {
                throwDeviceError(e, what);
            }
        }
        indirect = vertexValues(solution.elements, solution.vertices, perElement);
    }
    indirect_ = uploadBuffer(compute, float4s(indirect), "vertex indirect irradiance");
    lights_ = uploadLightSampling(scene, true);
}

cl_uint ViewPathInputs::bind(const PreparedScene& scene, cl::Kernel& kernel) const {
    const DeviceEnvironment& environment = scene.device().environment;
    setKernelArgs(kernel, DeviceScene::kArguments, deviceElements_.nodes, corners_, irradiance_, indirect_, caustic_,
                  caustics_, reflectance_, emission_, faceTextures_, srgb_, textured_, lights_.punctual,
                  lights_.punctualCount, lights_.directional, lights_.tree, lights_.surfaces.lights,
                  lights_.surfaces.ends, lights_.surfaces.lightOfPatch, lights_.surfaces.count, environment.info,
                  environment.texels, environment.rows, environment.columns);
    return DeviceScene::kArguments + 23;
}

}  // namespace rad
