#include "render/path_tracer.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "cl/buffers.h"
#include "cl/error.h"
#include "prepared/device_textures.h"
#include "util/error.h"

namespace rad {
namespace {

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

PathTraceResult pathTrace(const PreparedScene& scene, const View& view, const PathTraceOptions& options) {
    if (options.width < 1 || options.height < 1 || options.width > 16384 || options.height > 16384)
        throw InputError("image size " + std::to_string(options.width) + " x " + std::to_string(options.height) +
                         " is outside 1..16384 on each side");
    if (options.samples < 1) throw InputError("the path tracer needs at least one sample per pixel");
    const std::size_t pixels = static_cast<std::size_t>(options.width) * options.height;

    ComputeContext& compute = scene.compute();
    const Mesh& mesh = scene.mesh();
    const PatchSystem& patches = scene.patches();
    // Reflectance and emitted radiance of each face: those of its (front) patches.
    std::vector<cl_float4> reflectance(std::max<std::size_t>(mesh.faces.size(), 1)),
        emission(std::max<std::size_t>(mesh.faces.size(), 1));
    float largest = 0.0f;
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        reflectance[f] = float4Of(patches.reflectance[mesh.faces[f].frontPatch]);
        emission[f] = float4Of(patches.emission[mesh.faces[f].frontPatch]);
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
        cl::Buffer rhoBuffer = uploadBuffer(compute, reflectance, "path tracer's reflectances");
        cl::Buffer leBuffer = uploadBuffer(compute, emission, "path tracer's emission");
        PunctualLightSet set = scene.emitters().punctualLights();
        const auto lightCount = static_cast<cl_uint>(set.lights.size());
        if (set.lights.empty()) set.lights.resize(1);  // OpenCL buffers may not be empty
        if (set.tree.empty()) set.tree.resize(1);
        cl::Buffer lightBuffer = uploadBuffer(compute, set.lights, "path tracer's lights");
        cl::Buffer treeBuffer = uploadBuffer(compute, set.tree, "path tracer's light tree");
        cl::Buffer faceTextures = uploadBuffer(compute, scene.device().faceTextures, "faces' texture coordinates");
        cl::Buffer srgb = uploadBuffer(compute, srgbTable(), "sRGB table");
        cl::Buffer sumBuffer = allocateBuffer<cl_float4>(compute, pixels, "path tracer's image", CL_MEM_WRITE_ONLY);
        cl::Buffer rayBuffer = allocateBuffer<cl_uint>(compute, pixels, "path tracer's ray counts", CL_MEM_WRITE_ONLY);
        cl::Kernel kernel = scene.device().kernel(scene.device().program(compute, "pathtrace.cl"), "pathtrace");
        const DeviceEnvironment& environment = scene.device().environment;
        const cl_uint firstSampleArg = DeviceScene::kArguments + 16;  // then the sample count
        setKernelArgs(kernel, DeviceScene::kArguments, rhoBuffer, leBuffer, lightBuffer, lightCount,
                      static_cast<cl_uint>(set.directional), treeBuffer, faceTextures, srgb,
                      static_cast<cl_uint>(scene.device().textured ? 1 : 0), environment.info, environment.texels,
                      environment.rows, environment.columns, camera, static_cast<cl_uint>(options.width),
                      static_cast<cl_uint>(options.height), cl_uint{0}, cl_uint{0},
                      static_cast<cl_uint>(options.maxBounces), static_cast<cl_uint>(options.seed), lift, sumBuffer,
                      rayBuffer);
        for (std::uint32_t first = 0; first < options.samples; first += perLaunch) {
            const std::uint32_t count = std::min(perLaunch, options.samples - first);
            setKernelArgs(kernel, firstSampleArg, static_cast<cl_uint>(first), static_cast<cl_uint>(count));
            compute.launch(kernel, pixels);
            enqueueRead(compute, sumBuffer, part);
            rays = readBuffer<cl_uint>(compute, rayBuffer, pixels);
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
