#include "render/renderer.h"

#include "cl/buffers.h"
#include "cl/error.h"
#include "prepared/device_textures.h"
#include "render/face_materials.h"
#include "util/error.h"

static_assert(sizeof(CameraRays) == 64, "CameraRays must match the kernels' layout");
static_assert(sizeof(FaceTexture) == 112, "FaceTexture must match the kernels' layout");

namespace rad {
namespace {

}  // namespace

Image renderView(const PreparedScene& scene, const DeviceElements& elements, const MeshVertices& vertices,
                 const std::vector<glm::vec3>& vertexRadiance, const View& view, const RenderOptions& options,
                 const std::vector<glm::vec3>* vertexIrradiance) {
    ComputeContext& compute = scene.compute();
    if (options.width < 1 || options.height < 1 || options.width > 16384 || options.height > 16384)
        throw InputError("image size " + std::to_string(options.width) + " x " + std::to_string(options.height) +
                         " is outside 1..16384 on each side");
    const std::size_t pixels = static_cast<std::size_t>(options.width) * options.height;
    std::vector<cl_uint4> corners(vertices.corners.size());
    for (std::size_t e = 0; e < corners.size(); ++e)
        corners[e] = {{vertices.corners[e][0], vertices.corners[e][1], vertices.corners[e][2], 0}};
    std::vector<cl_float4> radiance(vertexRadiance.size());
    for (std::size_t v = 0; v < radiance.size(); ++v)
        radiance[v] = {{vertexRadiance[v].x, vertexRadiance[v].y, vertexRadiance[v].z, 0.0f}};
    if (corners.empty()) corners.resize(1);
    if (radiance.empty()) radiance.resize(1);
    // Textured faces are shown as Le(uv) + rho(uv) H / pi where the irradiance H is given.
    const bool textured = vertexIrradiance != nullptr && scene.device().textured;
    std::vector<cl_float4> irradiance;
    if (textured)
        for (const glm::vec3& h : *vertexIrradiance) irradiance.push_back(float4Of(h));
    if (irradiance.empty()) irradiance.resize(1);
    const std::vector<float> srgb = srgbTable();
    const CameraRays camera = cameraRays(view, options.width, options.height);

    // What mirrors and glass emit themselves, where the camera follows them (render.cl).
    const std::vector<cl_float4> emission = scene.device().specularFaces
                                                ? faceMaterialArrays(scene).emission
                                                : std::vector<cl_float4>(1, cl_float4{{0, 0, 0, 0}});
    std::vector<cl_float4> out(pixels);
    const MemoryReservation reservation = compute.reserve(
        corners.size() * sizeof(cl_uint4) + 2 * radiance.size() * sizeof(cl_float4) + pixels * sizeof(cl_float4) +
            scene.device().faceTextures.size() * sizeof(FaceTexture) + emission.size() * sizeof(cl_float4),
        std::max(corners.size() * sizeof(cl_uint4), pixels * sizeof(cl_float4)), "the image and vertex radiance");
    try {
        cl::Buffer cornerBuffer = uploadBuffer(compute, corners, "element corners");
        cl::Buffer radianceBuffer = uploadBuffer(compute, radiance, "vertex radiance");
        cl::Buffer image = allocateBuffer<cl_float4>(compute, pixels, "image", CL_MEM_WRITE_ONLY);
        cl::Buffer faceTextures = uploadBuffer(compute, scene.device().faceTextures, "faces' texture coordinates");
        cl::Buffer srgbBuffer = uploadBuffer(compute, srgb, "sRGB table");
        cl::Buffer irradianceBuffer = uploadBuffer(compute, irradiance, "vertex irradiance");
        cl::Buffer faceEmission = uploadBuffer(compute, emission, "faces' emission");
        cl::Kernel kernel = scene.device().kernel(scene.device().program(compute, "render.cl"), "render");
        const DeviceEnvironment& environment = scene.device().environment;
        setKernelArgs(kernel, DeviceScene::kArguments, elements.nodes, cornerBuffer, radianceBuffer, camera,
                      static_cast<cl_uint>(options.width), static_cast<cl_uint>(options.height),
                      static_cast<cl_uint>(options.samplesPerSide), environment.info, environment.texels,
                      environment.rows, environment.columns, static_cast<cl_uint>(options.wireframe ? 1 : 0),
                      faceTextures, srgbBuffer, irradianceBuffer, static_cast<cl_uint>(textured ? 1 : 0), faceEmission,
                      scene.device().lift, image);
        compute.launch(kernel, pixels);
        out = readBuffer<cl_float4>(compute, image, pixels);
    } catch (const cl::Error& e) {
        throwDeviceError(e, "rendering " + std::to_string(options.width) + " x " + std::to_string(options.height));
    }
    Image result;
    result.width = options.width;
    result.height = options.height;
    result.pixels.resize(pixels);
    for (std::size_t i = 0; i < pixels; ++i) result.pixels[i] = {out[i].s[0], out[i].s[1], out[i].s[2]};
    return result;
}

}  // namespace rad
