#include "prepared/device_scene.h"

#include <algorithm>
#include <cmath>
#include <iterator>

#include "cl/buffers.h"
#include "cl/error.h"
#include "prepared/device_environment.h"
#include "prepared/device_textures.h"
#include "prepared/specular_faces.h"

static_assert(sizeof(FaceInfo) == 32, "FaceInfo must match the kernels' layout");
static_assert(sizeof(RaySource) == 32, "RaySource must match the kernels' layout");
static_assert(sizeof(AlphaFace) == 48, "AlphaFace must match the kernels' layout");
static_assert(sizeof(TextureSlot) == 48, "TextureSlot must match the kernels' layout");

namespace rad {

DeviceScene::DeviceScene(ComputeContext& compute, const Mesh& mesh, const WideBvh& bvh, const Scene* scene,
                         const std::vector<glm::vec3>* patchReflectance)
    : patchCount(static_cast<std::uint32_t>(mesh.patches.size())) {
    TextureTable textures = scene ? buildTextureTable(*scene, mesh) : buildTextureTable(Scene{}, Mesh{});
    if (!scene) {
        textures.faceAlpha.assign(mesh.faces.size(), 0);
        textures.faceTextures.assign(1, FaceTexture{});
    }
    std::vector<FaceInfo> faceInfo(mesh.faces.size());
    float largest = 0.0f;
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        const Face& face = mesh.faces[f];
        for (const glm::vec3& p : face.p) largest = std::max({largest, std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
        faceInfo[f].frontPatch = face.frontPatch;
        faceInfo[f].backPatch = face.backPatch;
        faceInfo[f].subdivision = face.subdivision;
        faceInfo[f].alpha = textures.faceAlpha[f];
        for (int k = 0; k < 3; ++k) faceInfo[f].normal[k] = face.normal[k];
        faceInfo[f].normal[3] = 0.0f;
    }
    SamplingTables tables = buildSamplingTables(mesh);
    const EnvironmentTables outside = buildEnvironmentTables(scene ? *scene : Scene{});
    const SpecularFaceTable specularTable =
        scene ? buildSpecularFaces(*scene, mesh, patchReflectance) : SpecularFaceTable{{SpecularFace{}}, false};
    const std::uint64_t sizes[] = {outside.bytes(),
                                   bufferBytes<BvhNode>(bvh.nodes.size()),
                                   bufferBytes<LeafBlock>(bvh.blocks.size()),
                                   bufferBytes<FaceInfo>(faceInfo.size()),
                                   bufferBytes<SampleTriangle>(tables.triangles.size()),
                                   bufferBytes<std::uint32_t>(tables.cdf.size()),
                                   bufferBytes<AlphaFace>(textures.alpha.size()),
                                   bufferBytes<TextureSlot>(textures.slots.size()),
                                   bufferBytes<rad_uint>(textures.texels.size()),
                                   bufferBytes<SpecularFace>(specularTable.faces.size())};
    for (std::uint64_t size : sizes) bytes += size;
    reservation =
        compute.reserve(bytes, *std::max_element(std::begin(sizes), std::end(sizes)),
                        "the scene's BVH, faces and patches (" + std::to_string(mesh.patches.size()) + " patches)");
    nodes = uploadBuffer(compute, bvh.nodes, "BVH nodes");
    blocks = uploadBuffer(compute, bvh.blocks, "BVH leaves");
    faces = uploadBuffer(compute, faceInfo, "faces");
    triangles = uploadBuffer(compute, tables.triangles, "sampling triangles");
    cdf = uploadBuffer(compute, tables.cdf, "area tables");
    alpha = uploadBuffer(compute, textures.alpha, "alpha-masked faces");
    textureSlots = uploadBuffer(compute, textures.slots, "texture slots");
    texels = uploadBuffer(compute, textures.texels, "texels");
    specular = uploadBuffer(compute, specularTable.faces, "faces' specular reflection");
    environment = uploadEnvironment(compute, outside);
    specularFaces = specularTable.any;
    lift = largest * 0x1p-18f;
    masked = textures.alpha.size() > 1;
    faceTextures = std::move(textures.faceTextures);
    textured = textures.textured;
    surfaceRuns = std::move(tables.surfaceRuns);
}

cl::Kernel DeviceScene::kernel(cl::Program& program, const char* name) const {
    try {
        cl::Kernel kernel(program, name);
        setKernelArgs(kernel, 0
#define RAD_SCENE_ARGUMENT(type, member) , member
                      RAD_SCENE_BUFFERS(RAD_SCENE_ARGUMENT)
#undef RAD_SCENE_ARGUMENT
        );
        return kernel;
    } catch (const cl::Error& e) {
        throwDeviceError(e, std::string("creating the kernel ") + name);
    }
}

}  // namespace rad
