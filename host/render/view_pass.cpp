#include "render/view_pass.h"

#include <algorithm>
#include <iterator>

#include "cl/buffers.h"
#include "cl/error.h"
#include "light/direct_light_kernels.h"
#include "light/light_sampling.h"
#include "prepared/device_textures.h"
#include "render/view_path_inputs.h"
#include "shared_math.h"
#include "util/error.h"
#include "util/sample_streams.h"

namespace rad {

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
    ComputeContext& compute = scene.compute();
    const ViewPathSolution solution{elements, deviceElements, vertices, vertexIrradiance, vertexCaustic};
    const CameraRays camera = cameraRays(view, options.width, options.height);
    const std::string what = renderModeName(options.mode) + " camera pass";
    // Its own buffers, refused up front as renderView's are (the light-sampling tables, a few
    // entries per emitting patch, are left out): what the paths read, and the pixels' sums and
    // ray counts.
    const std::uint64_t pixels =
        std::uint64_t{static_cast<std::uint32_t>(options.width)} * static_cast<std::uint32_t>(options.height);
    const ViewPathInputs::Bytes inputs = ViewPathInputs::deviceBytes(scene, solution, options.mode);
    const std::uint64_t sums = pixels * sizeof(cl_float4), counts = pixels * sizeof(cl_uint);
    const MemoryReservation reservation = compute.reserve(inputs.total + sums + counts,
                                                          std::max({inputs.largest, sums, counts}),
                                                          "the " + what + "'s buffers");
    try {
        const ViewPathInputs paths(scene, solution, options.mode, options.indirectRaysPerElement, options.seed);
        cl::Kernel kernel = scene.device().kernel(scene.device().program(compute, "view_pass.cl"), "view_pass");
        const cl_uint next = paths.bind(scene, kernel);
        const cl_uint firstSampleArg = next + 3;  // then the sample count
        setKernelArgs(kernel, next, camera, static_cast<cl_uint>(options.width), static_cast<cl_uint>(options.height),
                      cl_uint{0}, cl_uint{0}, viewPathMode(options.mode),
                      static_cast<cl_uint>(options.seed), scene.device().lift,
                      static_cast<float>(options.nearPatches * scene.mesh().patchSize));
        return estimatePixels(compute, kernel, firstSampleArg, firstSampleArg + 6, options.width, options.height,
                              options.samples, what);
    } catch (const cl::Error& e) {
        throwDeviceError(e, what + " " + std::to_string(options.width) + " x " + std::to_string(options.height));
    }
}

}  // namespace rad
