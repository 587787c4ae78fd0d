#include "render/path_tracer.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "cl/buffers.h"
#include "cl/error.h"
#include "light/light_sampling.h"
#include "prepared/device_textures.h"
#include "render/face_materials.h"
#include "util/error.h"

namespace rad {

PathTraceResult pathTrace(const PreparedScene& scene, const View& view, const PathTraceOptions& options) {
    if (options.width < 1 || options.height < 1 || options.width > 16384 || options.height > 16384)
        throw InputError("image size " + std::to_string(options.width) + " x " + std::to_string(options.height) +
                         " is outside 1..16384 on each side");
    if (options.samples < 1) throw InputError("the path tracer needs at least one sample per pixel");
    const std::size_t pixels = static_cast<std::size_t>(options.width) * options.height;

    ComputeContext& compute = scene.compute();
    const FaceMaterialArrays materials = faceMaterialArrays(scene);
    const std::vector<cl_float4>& reflectance = materials.reflectance;
    const float lift = scene.device().lift;
    const CameraRays camera = cameraRays(view, options.width, options.height);
    const std::uint64_t materialBytes = 2 * reflectance.size() * sizeof(cl_float4);
    const std::uint64_t imageBytes = pixels * (sizeof(cl_float4) + sizeof(cl_uint));
    const MemoryReservation reservation = compute.reserve(
        materialBytes + imageBytes, std::max(reflectance.size() * sizeof(cl_float4), pixels * sizeof(cl_float4)),
        "the path tracer's materials and image");
    try {
        cl::Buffer rhoBuffer = uploadBuffer(compute, reflectance, "path tracer's reflectances");
        cl::Buffer leBuffer = uploadBuffer(compute, materials.emission, "path tracer's emission");
        const DeviceLightSampling lights = uploadLightSampling(scene, options.lightSampling);
        cl::Buffer faceTextures = uploadBuffer(compute, scene.device().faceTextures, "faces' texture coordinates");
        cl::Buffer srgb = uploadBuffer(compute, srgbTable(), "sRGB table");
        cl::Kernel kernel = scene.device().kernel(scene.device().program(compute, "pathtrace.cl"), "pathtrace");
        const DeviceEnvironment& environment = scene.device().environment;
        const cl_uint firstSampleArg = DeviceScene::kArguments + 20;  // then the sample count
        setKernelArgs(kernel, DeviceScene::kArguments, rhoBuffer, leBuffer, lights.punctual, lights.punctualCount,
                      lights.directional, lights.tree, faceTextures, srgb,
                      static_cast<cl_uint>(scene.device().textured ? 1 : 0), lights.surfaces.lights,
                      lights.surfaces.ends, lights.surfaces.lightOfPatch, lights.surfaces.count, environment.info,
                      environment.texels, environment.rows, environment.columns, camera,
                      static_cast<cl_uint>(options.width), static_cast<cl_uint>(options.height), cl_uint{0}, cl_uint{0},
                      static_cast<cl_uint>(options.maxBounces), static_cast<cl_uint>(options.seed), lift);
        return estimatePixels(compute, kernel, firstSampleArg, firstSampleArg + 5, options.width, options.height,
                              options.samples, "path tracing");
    } catch (const cl::Error& e) {
        throwDeviceError(e, "path tracing " + std::to_string(options.width) + " x " + std::to_string(options.height));
    }
}

}  // namespace rad
