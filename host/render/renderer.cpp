#include "render/renderer.h"

#include "cl/buffers.h"
#include "cl/error.h"
#include "mesh/patch_textures.h"
#include "scene/texture_sampling.h"
#include "util/error.h"

static_assert(sizeof(CameraRays) == 64, "CameraRays must match the kernels' layout");
static_assert(sizeof(FaceTexture) == 112, "FaceTexture must match the kernels' layout");

namespace rad {
namespace {

// The faces' texture coordinates and factors for the camera pass (kernels/render.cl,
// Texturing); the textures themselves are the scene's (DeviceScene::textureSlots). At least one
// entry: OpenCL buffers may not be empty.
struct DeviceTexturing {
    std::vector<FaceTexture> faces;
    std::vector<float> srgb;
    bool present = false;
};

DeviceTexturing deviceTexturing(const PreparedScene& prepared) {
    const Scene& scene = prepared.scene();
    const Mesh& mesh = prepared.mesh();
    DeviceTexturing t;
    t.srgb.resize(256);
    for (int i = 0; i < 256; ++i) t.srgb[static_cast<std::size_t>(i)] = srgbToLinear(static_cast<std::uint8_t>(i));
    t.faces.resize(mesh.faces.size());
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        const Face& face = mesh.faces[f];
        const auto m = static_cast<std::size_t>(face.material);
        const Material& material = scene.materials[m];
        FaceTexture& out = t.faces[f];
        out.baseSlot = prepared.device().baseSlot[m];
        out.emissiveSlot = prepared.device().emissiveSlot[m];
        if (out.baseSlot < 0 && out.emissiveSlot < 0) continue;
        t.present = true;
        const Surface& surface = scene.surfaces[face.sceneSurface];
        const double corner[3][2] = {{0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}};
        for (int k = 0; k < 3; ++k) {
            const glm::vec2 base =
                texCoordAt(surface, face.sceneTriangle, material.baseColorTexture.texCoord, corner[k][0], corner[k][1]);
            const glm::vec2 emissive =
                texCoordAt(surface, face.sceneTriangle, material.emissiveTexture.texCoord, corner[k][0], corner[k][1]);
            out.baseUv[2 * k] = base.x;
            out.baseUv[2 * k + 1] = base.y;
            out.emissiveUv[2 * k] = emissive.x;
            out.emissiveUv[2 * k + 1] = emissive.y;
        }
        for (int c = 0; c < 3; ++c) {
            out.reflectance[c] = material.reflectance[c];
            out.emission[c] = material.emission[c];
        }
    }
    if (!t.present) t.faces.assign(1, FaceTexture{});
    return t;
}

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
    DeviceTexturing texturing = vertexIrradiance ? deviceTexturing(scene) : DeviceTexturing{};
    std::vector<cl_float4> irradiance;
    if (texturing.present)
        for (const glm::vec3& h : *vertexIrradiance) irradiance.push_back(float4Of(h));
    else
        texturing = {{FaceTexture{}}, std::vector<float>(256, 0.0f), false};
    if (irradiance.empty()) irradiance.resize(1);
    const CameraRays camera = cameraRays(view, options.width, options.height);

    std::vector<cl_float4> out(pixels);
    const MemoryReservation reservation = compute.reserve(
        corners.size() * sizeof(cl_uint4) + 2 * radiance.size() * sizeof(cl_float4) + pixels * sizeof(cl_float4) +
            texturing.faces.size() * sizeof(FaceTexture),
        std::max(corners.size() * sizeof(cl_uint4), pixels * sizeof(cl_float4)), "the image and vertex radiance");
    try {
        cl::Buffer cornerBuffer = uploadBuffer(compute, corners, "element corners");
        cl::Buffer radianceBuffer = uploadBuffer(compute, radiance, "vertex radiance");
        cl::Buffer image = allocateBuffer<cl_float4>(compute, pixels, "image", CL_MEM_WRITE_ONLY);
        cl::Buffer faceTextures = uploadBuffer(compute, texturing.faces, "faces' texture coordinates");
        cl::Buffer srgb = uploadBuffer(compute, texturing.srgb, "sRGB table");
        cl::Buffer irradianceBuffer = uploadBuffer(compute, irradiance, "vertex irradiance");
        cl::Kernel kernel = scene.device().kernel(compute.program("render.cl"), "render");
        setKernelArgs(kernel, DeviceScene::kArguments, elements.nodes, cornerBuffer, radianceBuffer, camera,
                      static_cast<cl_uint>(options.width), static_cast<cl_uint>(options.height),
                      static_cast<cl_uint>(options.samplesPerSide), float4Of(scene.scene().sky),
                      static_cast<cl_uint>(options.wireframe ? 1 : 0), faceTextures, srgb, irradianceBuffer,
                      static_cast<cl_uint>(texturing.present ? 1 : 0), image);
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
