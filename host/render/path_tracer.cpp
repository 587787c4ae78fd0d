#include "render/path_tracer.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "cl/error.h"
#include "util/error.h"

namespace rad {
namespace {

cl_float4 float4Of(const glm::vec3& v) { return {{v.x, v.y, v.z, 0.0f}}; }

// Paths per launch, about: enough to keep a GPU busy, few enough that a launch stays short.
// It depends on the image size alone, so the sums (and the image) do not depend on the device.
constexpr std::uint64_t kPathsPerLaunch = 1u << 20;
// The most paths one work item (one pixel) traces in a launch. Without it a tiny image would
// put up to kPathsPerLaunch paths in one work item: one launch long enough for a GPU's
// watchdog to kill, a float sum of a million terms in the kernel, and a ray count that could
// overflow its 32 bits. A constant, so the launches (and the image) still depend only on the
// image size, the seed and the sample count. Images of 4096 pixels or more never reach it.
constexpr std::uint64_t kMaxSamplesPerLaunch = 256;

}  // namespace

PathTraceResult pathTrace(ComputeContext& compute, const Scene& scene, const Mesh& mesh, const DeviceScene& device,
                          const View& view, const PathTraceOptions& options) {
    if (options.width < 1 || options.height < 1 || options.width > 16384 || options.height > 16384)
        throw InputError("image size " + std::to_string(options.width) + " x " + std::to_string(options.height) +
                         " is outside 1..16384 on each side");
    if (options.samples < 1) throw InputError("the path tracer needs at least one sample per pixel");
    const std::size_t pixels = static_cast<std::size_t>(options.width) * options.height;

    // Reflectance and emitted radiance of each face, from its material.
    std::vector<cl_float4> reflectance(std::max<std::size_t>(mesh.faces.size(), 1)),
        emission(std::max<std::size_t>(mesh.faces.size(), 1));
    float largest = 0.0f;
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        const Material& m = scene.materials[static_cast<std::size_t>(mesh.faces[f].material)];
        reflectance[f] = float4Of(m.reflectance);
        emission[f] = float4Of(m.emission);
        for (const glm::vec3& p : mesh.faces[f].p)
            largest = std::max({largest, std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
    }
    const float lift = largest * 0x1p-18f;  // 32 ulps of the scene's largest coordinate
    const CameraRays camera = cameraRays(view, options.width, options.height);
    const std::uint64_t mostPerLaunch = std::min<std::uint64_t>(kMaxSamplesPerLaunch, options.samples);
    const std::uint32_t perLaunch =
        static_cast<std::uint32_t>(std::clamp<std::uint64_t>(kPathsPerLaunch / pixels, 1, mostPerLaunch));

    const std::uint64_t materialBytes = 2 * reflectance.size() * sizeof(cl_float4);
    const std::uint64_t imageBytes = pixels * (sizeof(cl_float4) + sizeof(cl_uint));
    const MemoryReservation reservation = compute.reserve(
        materialBytes + imageBytes, std::max(reflectance.size() * sizeof(cl_float4), pixels * sizeof(cl_float4)),
        "the path tracer's materials and image");

    std::vector<glm::dvec3> sum(pixels, glm::dvec3(0.0));
    std::vector<cl_float4> part(pixels);
    std::vector<cl_uint> rays(pixels);
    PathTraceResult result;
    try {
        cl::Buffer rhoBuffer(compute.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                             reflectance.size() * sizeof(cl_float4), reflectance.data());
        cl::Buffer leBuffer(compute.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, emission.size() * sizeof(cl_float4),
                            emission.data());
        cl::Buffer sumBuffer(compute.context(), CL_MEM_WRITE_ONLY, pixels * sizeof(cl_float4));
        cl::Buffer rayBuffer(compute.context(), CL_MEM_WRITE_ONLY, pixels * sizeof(cl_uint));
        cl::Kernel kernel(compute.program("pathtrace.cl"), "pathtrace");
        int arg = 0;
        kernel.setArg(arg++, device.nodes);
        kernel.setArg(arg++, device.blocks);
        kernel.setArg(arg++, device.faces);
        kernel.setArg(arg++, rhoBuffer);
        kernel.setArg(arg++, leBuffer);
        kernel.setArg(arg++, sizeof camera, &camera);
        kernel.setArg(arg++, static_cast<cl_uint>(options.width));
        kernel.setArg(arg++, static_cast<cl_uint>(options.height));
        const int firstSampleArg = arg++, sampleCountArg = arg++;
        kernel.setArg(arg++, static_cast<cl_uint>(options.maxBounces));
        kernel.setArg(arg++, static_cast<cl_uint>(options.seed));
        kernel.setArg(arg++, lift);
        kernel.setArg(arg++, sumBuffer);
        kernel.setArg(arg++, rayBuffer);
        for (std::uint32_t first = 0; first < options.samples; first += perLaunch) {
            const std::uint32_t count = std::min(perLaunch, options.samples - first);
            kernel.setArg(firstSampleArg, static_cast<cl_uint>(first));
            kernel.setArg(sampleCountArg, static_cast<cl_uint>(count));
            compute.launch(kernel, pixels);
            compute.queue().enqueueReadBuffer(sumBuffer, CL_FALSE, 0, pixels * sizeof(cl_float4), part.data());
            compute.queue().enqueueReadBuffer(rayBuffer, CL_TRUE, 0, pixels * sizeof(cl_uint), rays.data());
            for (std::size_t i = 0; i < pixels; ++i) {
                sum[i] += glm::dvec3(part[i].s[0], part[i].s[1], part[i].s[2]);
                result.rays += rays[i];
            }
        }
    } catch (const cl::Error& e) {
        throwDeviceError(e, "path tracing " + std::to_string(options.width) + " x " + std::to_string(options.height));
    }
    result.image.width = options.width;
    result.image.height = options.height;
    result.image.pixels.resize(pixels);
    for (std::size_t i = 0; i < pixels; ++i) result.image.pixels[i] = glm::vec3(sum[i] / static_cast<double>(options.samples));
    return result;
}

}  // namespace rad
