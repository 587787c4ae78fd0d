#include "render/renderer.h"

#include <map>

#include "cl/buffers.h"
#include "cl/error.h"
#include "mesh/patch_textures.h"
#include "scene/texture_sampling.h"
#include "util/error.h"

static_assert(sizeof(CameraRays) == 64, "CameraRays must match the kernels' layout");
static_assert(sizeof(TextureSlot) == 48, "TextureSlot must match the kernels' layout");
static_assert(sizeof(FaceTexture) == 112, "FaceTexture must match the kernels' layout");

namespace rad {
namespace {

// What the camera pass reads of the scene's textures (kernels/render.cl, Texturing). Each
// buffer holds at least one entry: OpenCL buffers may not be empty.
struct DeviceTexturing {
    std::vector<FaceTexture> faces;
    std::vector<TextureSlot> slots;
    std::vector<cl_uchar4> texels;
    std::vector<float> srgb;
    bool present = false;
};

cl_uint wrapFlag(TextureRef::Wrap wrap) {
    return wrap == TextureRef::Wrap::ClampToEdge      ? RAD_WRAP_CLAMP
           : wrap == TextureRef::Wrap::MirroredRepeat ? RAD_WRAP_MIRROR
                                                      : RAD_WRAP_REPEAT;
}

DeviceTexturing deviceTexturing(const Scene& scene, const Mesh& mesh) {
    DeviceTexturing t;
    t.srgb.resize(256);
    for (int i = 0; i < 256; ++i) t.srgb[static_cast<std::size_t>(i)] = srgbToLinear(static_cast<std::uint8_t>(i));
    std::vector<cl_uint> imageOffset;
    for (const TextureImage& image : scene.images) {
        imageOffset.push_back(static_cast<cl_uint>(t.texels.size()));
        for (std::size_t k = 0; k + 3 < image.rgba.size(); k += 4)
            t.texels.push_back({{image.rgba[k], image.rgba[k + 1], image.rgba[k + 2], image.rgba[k + 3]}});
    }
    std::map<std::pair<int, int>, cl_int> slotOf;  // (material, 0 base / 1 emissive) -> slot
    auto slot = [&](int material, int which, const TextureRef& ref) -> cl_int {
        if (!ref.present()) return -1;
        const auto key = std::make_pair(material, which);
        const auto found = slotOf.find(key);
        if (found != slotOf.end()) return found->second;
        const TextureImage& image = scene.images[static_cast<std::size_t>(ref.image)];
        TextureSlot s{};
        s.offset = imageOffset[static_cast<std::size_t>(ref.image)];
        s.width = static_cast<cl_uint>(image.width);
        s.height = static_cast<cl_uint>(image.height);
        s.flags = wrapFlag(ref.wrapS) | (wrapFlag(ref.wrapT) << 2) | (ref.nearest ? 16u : 0u);
        for (int r = 0; r < 2; ++r)
            for (int c = 0; c < 3; ++c) s.rows[r][c] = ref.transform[c][r];
        t.slots.push_back(s);
        return slotOf[key] = static_cast<cl_int>(t.slots.size() - 1);
    };
    t.faces.resize(mesh.faces.size());
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        const Face& face = mesh.faces[f];
        const Material& material = scene.materials[static_cast<std::size_t>(face.material)];
        FaceTexture& out = t.faces[f];
        out.baseSlot = slot(face.material, 0, material.baseColorTexture);
        out.emissiveSlot = slot(face.material, 1, material.emissiveTexture);
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
    if (t.slots.empty()) t.slots.resize(1);
    if (t.texels.empty()) t.texels.resize(1);
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
    DeviceTexturing texturing = vertexIrradiance ? deviceTexturing(scene.scene(), scene.mesh()) : DeviceTexturing{};
    std::vector<cl_float4> irradiance;
    if (texturing.present)
        for (const glm::vec3& h : *vertexIrradiance) irradiance.push_back(float4Of(h));
    else
        texturing = {{FaceTexture{}}, {TextureSlot{}}, {cl_uchar4{}}, std::vector<float>(256, 0.0f), false};
    if (irradiance.empty()) irradiance.resize(1);
    const CameraRays camera = cameraRays(view, options.width, options.height);

    std::vector<cl_float4> out(pixels);
    const MemoryReservation reservation = compute.reserve(
        corners.size() * sizeof(cl_uint4) + 2 * radiance.size() * sizeof(cl_float4) + pixels * sizeof(cl_float4) +
            texturing.faces.size() * sizeof(FaceTexture) + texturing.texels.size() * sizeof(cl_uchar4),
        std::max(corners.size() * sizeof(cl_uint4), pixels * sizeof(cl_float4)), "the image and vertex radiance");
    try {
        cl::Buffer cornerBuffer = uploadBuffer(compute, corners, "element corners");
        cl::Buffer radianceBuffer = uploadBuffer(compute, radiance, "vertex radiance");
        cl::Buffer image = allocateBuffer<cl_float4>(compute, pixels, "image", CL_MEM_WRITE_ONLY);
        cl::Buffer faceTextures = uploadBuffer(compute, texturing.faces, "faces' texture coordinates");
        cl::Buffer slots = uploadBuffer(compute, texturing.slots, "texture slots");
        cl::Buffer texels = uploadBuffer(compute, texturing.texels, "texels");
        cl::Buffer srgb = uploadBuffer(compute, texturing.srgb, "sRGB table");
        cl::Buffer irradianceBuffer = uploadBuffer(compute, irradiance, "vertex irradiance");
        cl::Kernel kernel = scene.device().kernel(compute.program("render.cl"), "render");
        setKernelArgs(kernel, DeviceScene::kArguments, elements.nodes, cornerBuffer, radianceBuffer, camera,
                      static_cast<cl_uint>(options.width), static_cast<cl_uint>(options.height),
                      static_cast<cl_uint>(options.samplesPerSide), float4Of(scene.scene().sky),
                      static_cast<cl_uint>(options.wireframe ? 1 : 0), faceTextures, slots, texels, srgb,
                      irradianceBuffer, static_cast<cl_uint>(texturing.present ? 1 : 0), image);
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
