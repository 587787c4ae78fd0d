#include "render/view_pass.h"

#include <algorithm>
#include <iterator>

#include "cl/buffers.h"
#include "cl/error.h"
#include "light/direct_light_kernels.h"
#include "light/light_sampling.h"
#include "prepared/device_textures.h"
#include "render/face_materials.h"
#include "shared_math.h"
#include "util/error.h"
#include "util/sample_streams.h"

namespace rad {
namespace {

constexpr cl_uint kDirectMode = 1, kFinalGatherMode = 2;  // kernels/view_pass.cl

std::vector<cl_float4> float4s(const std::vector<glm::vec3>& values) {
    std::vector<cl_float4> out(std::max<std::size_t>(values.size(), 1));
    for (std::size_t i = 0; i < values.size(); ++i) out[i] = float4Of(values[i]);
    return out;
}

// The faces' materials on the device, as both kernels of view_pass.cl read them, and whether the
// solution holds the light that came by way of mirrors and glass apart (then rays that meet them
// bring no light the solution holds).
struct DeviceMaterials {
    cl::Buffer reflectance, emission, faceTextures, srgb;
    cl_uint textured = 0, caustics = 0;
};

// The solution's indirect irradiance per element (element_indirect in kernels/view_pass.cl).
std::vector<glm::vec3> elementIndirect(const PreparedScene& scene, const ElementMesh& elements,
                                       const DeviceElements& deviceElements, const cl::Buffer& corners,
                                       const cl::Buffer& irradiance, const DeviceMaterials& m,
                                       const ViewPassOptions& options) {
    ComputeContext& compute = scene.compute();
    const std::size_t count = elements.elements().size();
    std::vector<glm::vec3> out(count, glm::vec3(0.0f));
    if (count == 0) return out;
    const std::string what = "gathering the solution's indirect light over " + std::to_string(count) + " elements";
    cl::Buffer result = allocateBuffer<cl_float4>(compute, count, what, CL_MEM_WRITE_ONLY);
    launchOverElements(scene, "view_pass.cl", "element_indirect", directLightElements(scene.mesh(), elements),
                       options.indirectRaysPerElement, what, [&](cl::Kernel& kernel, cl_uint next) {
                           setKernelArgs(kernel, next, deviceElements.nodes, corners, irradiance, m.reflectance,
                                         m.emission, m.faceTextures, m.srgb, m.textured, m.caustics,
                                         static_cast<cl_uint>(options.indirectRaysPerElement),
                                         static_cast<cl_uint>(rad_hash2(options.seed, kViewIndirectStream)), result);
                       });
    try {
        const std::vector<cl_float4> values = readBuffer<cl_float4>(compute, result, count);
        for (std::size_t e = 0; e < count; ++e) out[e] = {values[e].s[0], values[e].s[1], values[e].s[2]};
    } catch (const cl::Error& e) {
        throwDeviceError(e, what);
    }
    return out;
}

}  // namespace

std::string renderModeName(RenderMode mode) {
    switch (mode) {
        case RenderMode::radiosity:
            return "radiosity";
        case RenderMode::direct:
            return "direct";
        case RenderMode::finalGather:
            return "final-gather";
    }
    return "radiosity";
}

std::optional<RenderMode> renderModeNamed(const std::string& name) {
    for (RenderMode m : {RenderMode::radiosity, RenderMode::direct, RenderMode::finalGather})
        if (renderModeName(m) == name) return m;
    return std::nullopt;
}

PixelEstimate renderViewPass(const PreparedScene& scene, const ElementMesh& elements,
                             const DeviceElements& deviceElements, const MeshVertices& vertices,
                             const std::vector<glm::vec3>& vertexIrradiance, const View& view,
                             const ViewPassOptions& options, const std::vector<glm::vec3>& vertexCaustic) {
    if (options.width < 1 || options.height < 1 || options.width > 16384 || options.height > 16384)
        throw InputError("image size " + std::to_string(options.width) + " x " + std::to_string(options.height) +
                         " is outside 1..16384 on each side");
    if (options.samples < 1) throw InputError("the camera pass needs at least one sample per pixel");
    if (options.mode == RenderMode::radiosity)
        throw InputError("renderViewPass draws the direct and final-gather modes; radiosity is renderView's");
    if (!vertexCaustic.empty() && vertexCaustic.size() != vertexIrradiance.size())
        throw InputError("the caustic light is given at " + std::to_string(vertexCaustic.size()) +
                         " vertices, the irradiance at " + std::to_string(vertexIrradiance.size()));
    ComputeContext& compute = scene.compute();
    std::vector<cl_uint4> corners(std::max<std::size_t>(vertices.corners.size(), 1));
    for (std::size_t e = 0; e < vertices.corners.size(); ++e)
        corners[e] = {{vertices.corners[e][0], vertices.corners[e][1], vertices.corners[e][2], 0}};
    const FaceMaterialArrays materials = faceMaterialArrays(scene);
    const CameraRays camera = cameraRays(view, options.width, options.height);
    const std::string what = renderModeName(options.mode) + " camera pass";
    // Its own buffers, refused up front as renderView's are (the light-sampling tables, a few
    // entries per emitting patch, are left out): corners, the vertices' irradiance, indirect and
    // caustic light, the faces' materials, and the pixels' sums and ray counts.
    const std::uint64_t pixels =
        std::uint64_t{static_cast<std::uint32_t>(options.width)} * static_cast<std::uint32_t>(options.height);
    const std::uint64_t vertexBytes = std::max<std::size_t>(vertexIrradiance.size(), 1) * sizeof(cl_float4);
    const std::uint64_t sizes[] = {corners.size() * sizeof(cl_uint4),
                                   vertexBytes,
                                   options.mode == RenderMode::direct ? vertexBytes : sizeof(cl_float4),
                                   vertexCaustic.empty() ? sizeof(cl_float4) : vertexBytes,
                                   2 * materials.reflectance.size() * sizeof(cl_float4),
                                   scene.device().faceTextures.size() * sizeof(FaceTexture),
                                   pixels * sizeof(cl_float4),
                                   pixels * sizeof(cl_uint)};
    std::uint64_t total = 0;
    for (std::uint64_t size : sizes) total += size;
    const MemoryReservation reservation =
        compute.reserve(total, *std::max_element(std::begin(sizes), std::end(sizes)), "the " + what + "'s buffers");
    try {
        cl::Buffer cornerBuffer = uploadBuffer(compute, corners, "element corners");
        cl::Buffer irradiance = uploadBuffer(compute, float4s(vertexIrradiance), "vertex irradiance");
        DeviceMaterials m;
        m.reflectance = uploadBuffer(compute, materials.reflectance, "faces' reflectances");
        m.emission = uploadBuffer(compute, materials.emission, "faces' emission");
        m.faceTextures = uploadBuffer(compute, scene.device().faceTextures, "faces' texture coordinates");
        m.srgb = uploadBuffer(compute, srgbTable(), "sRGB table");
        m.textured = scene.device().textured ? 1 : 0;
        m.caustics = vertexCaustic.empty() ? 0 : 1;
        cl::Buffer causticBuffer = uploadBuffer(compute, float4s(vertexCaustic), "vertex caustic irradiance");
        std::vector<glm::vec3> indirect;
        if (options.mode == RenderMode::direct)
            indirect =
                vertexValues(elements, vertices,
                             elementIndirect(scene, elements, deviceElements, cornerBuffer, irradiance, m, options));
        cl::Buffer indirectBuffer = uploadBuffer(compute, float4s(indirect), "vertex indirect irradiance");
        const DeviceLightSampling lights = uploadLightSampling(scene, true);
        cl::Kernel kernel = scene.device().kernel(scene.device().program(compute, "view_pass.cl"), "view_pass");
        const DeviceEnvironment& environment = scene.device().environment;
        const cl_uint firstSampleArg = DeviceScene::kArguments + 26;  // then the sample count
        setKernelArgs(kernel, DeviceScene::kArguments, deviceElements.nodes, cornerBuffer, irradiance, indirectBuffer,
                      causticBuffer, m.caustics, m.reflectance, m.emission, m.faceTextures, m.srgb, m.textured,
                      lights.punctual, lights.punctualCount, lights.directional, lights.tree, lights.surfaces.lights,
                      lights.surfaces.ends, lights.surfaces.lightOfPatch, lights.surfaces.count, environment.info,
                      environment.texels, environment.rows, environment.columns, camera,
                      static_cast<cl_uint>(options.width), static_cast<cl_uint>(options.height), cl_uint{0}, cl_uint{0},
                      options.mode == RenderMode::direct ? kDirectMode : kFinalGatherMode,
                      static_cast<cl_uint>(options.seed), scene.device().lift,
                      static_cast<float>(options.nearPatches * scene.mesh().patchSize));
        return estimatePixels(compute, kernel, firstSampleArg, firstSampleArg + 6, options.width, options.height,
                              options.samples, what);
    } catch (const cl::Error& e) {
        throwDeviceError(e, what + " " + std::to_string(options.width) + " x " + std::to_string(options.height));
    }
}

}  // namespace rad
