#include "device/device_scene.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "device/device_environment.h"
#include "device/device_textures.h"
#include "device/face_layers.h"
#include "device/face_normal_maps.h"
#include "device/specular_faces.h"
#include "scene/ggx_albedo.h"

namespace rad {
namespace {

std::vector<FaceInfo> faceInfo(const Mesh& mesh, const std::vector<rad_uint>& faceAlpha) {
    std::vector<FaceInfo> out(mesh.faces.size());
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        const Face& face = mesh.faces[f];
        out[f].frontPatch = face.frontPatch;
        out[f].backPatch = face.backPatch;
        out[f].subdivision = face.subdivision;
        out[f].alpha = faceAlpha[f];
        for (int k = 0; k < 3; ++k) out[f].normal[k] = face.normal[k];
        out[f].normal[3] = 0.0f;
    }
    return out;
}

// 32 ulps of the scene's largest coordinate.
float sceneLift(const Mesh& mesh) {
    float largest = 0.0f;
    for (const Face& face : mesh.faces)
        for (const glm::vec3& p : face.p) largest = std::max({largest, std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
    return largest * 0x1p-18f;
}

// Per face, its front patch's shading colour (PatchSystem::shadingColour) and emission.
std::vector<FaceMaterial> faceMaterials(const Mesh& mesh, const std::vector<glm::vec3>& reflectance,
                                        const std::vector<glm::vec3>& emission) {
    std::vector<FaceMaterial> out(mesh.faces.size());
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        const std::uint32_t patch = mesh.faces[f].frontPatch;
        for (int c = 0; c < 3; ++c) {
            out[f].reflectance[c] = reflectance[patch][c];
            out[f].emission[c] = emission[patch][c];
        }
    }
    return out;
}

}  // namespace

DeviceScene::DeviceScene(ComputeContext& compute, const DeviceSceneInputs& inputs)
    : compute_(&compute), patchCount_(static_cast<std::uint32_t>(inputs.mesh.patches.size())) {
    const Mesh& mesh = inputs.mesh;
    TextureTable textures = buildTextureTable(inputs.scene, mesh);
    SamplingTables tables = buildSamplingTables(mesh);
    const SpecularFaceTable specularTable = buildSpecularFaces(inputs.scene, mesh, &inputs.patchReflectance);
    const FaceLayerTable layerTable = buildFaceLayers(inputs.scene, mesh, textures);
    const FaceNormalMapTable normalMapTable = buildFaceNormalMaps(inputs.scene, mesh, textures);
    // under a layer the patches' reflectance holds the layer's light too: the kernels need the base colour
    if (layerTable.any && !inputs.patchShadingColour)
        throw std::invalid_argument("DeviceScene: a scene with specular layers needs the patches' shading colours");
    const EnvironmentTables outside = buildEnvironmentTables(inputs.scene);
    const std::string patches = " (" + std::to_string(mesh.patches.size()) + " patches)";
    nodes = DeviceArray<BvhNode>::upload(compute, inputs.bvh.nodes, "BVH nodes" + patches);
    blocks = DeviceArray<LeafBlock>::upload(compute, inputs.bvh.blocks, "BVH leaves" + patches);
    faces = DeviceArray<FaceInfo>::upload(compute, faceInfo(mesh, textures.faceAlpha), "faces" + patches);
    triangles = DeviceArray<SampleTriangle>::upload(compute, tables.triangles, "sampling triangles" + patches);
    cdf = DeviceArray<rad_uint>::upload(compute, tables.cdf, "area tables" + patches);
    alpha = DeviceArray<AlphaFace>::upload(compute, textures.alpha, "alpha-masked faces");
    textureSlots = DeviceArray<TextureSlot>::upload(compute, textures.slots, "texture slots");
    texels = DeviceArray<rad_uint>::upload(compute, textures.texels, "texels");
    specular = DeviceArray<SpecularFace>::upload(compute, specularTable.faces, "faces' specular reflection");
    faceTextures = DeviceArray<FaceTexture>::upload(compute, textures.faceTextures, "faces' texture coordinates");
    srgb = DeviceArray<float>::upload(compute, srgbTable(), "sRGB table");
    faceLayers = DeviceArray<FaceLayer>::upload(compute, layerTable.faces, "faces' specular layers");
    faceSpecularTextures = DeviceArray<FaceSpecularTextures>::upload(compute, layerTable.specularTextures,
                                                                     "faces' specular textures");
    // the GGX lobes' albedo table, where layers or rough metals look it up (-DRAD_GGX_TABLE)
    ggxTable_ = layerTable.any || specularTable.glossy;
    ggxAlbedo = DeviceArray<float>::upload(compute, ggxTable_ ? ggxAlbedoDeviceTable() : std::vector<float>(1, 0.0f),
                                           "GGX albedo table");
    faceNormalMaps = DeviceArray<FaceNormalMap>::upload(compute, normalMapTable.faces, "faces' normal maps");
    environmentTexels = DeviceArray<rad_float4>::upload(compute, outside.texels, "environment map");
    environmentRows = DeviceArray<rad_uint>::upload(compute, outside.rows, "environment map's row table");
    environmentColumns = DeviceArray<rad_uint>::upload(compute, outside.columns, "environment map's column tables");
    info_.environment = outside.info;
    info_.textured = textures.textured ? 1 : 0;
    info_.lift = sceneLift(mesh);
    specularFaces_ = specularTable.any;
    layered_ = layerTable.any;
    normalMapped_ = normalMapTable.any;
    masked_ = textures.alpha.size() > 1;
    surfaceRuns_ = std::move(tables.surfaceRuns);
    uploadLights(inputs);
}

std::shared_ptr<const DeviceElements> DeviceScene::elements(const ElementMesh& mesh) const {
    if (!elements_ || elements_->elementCount != mesh.elements().size() ||
        elements_->contents != DeviceElements::fingerprint(mesh))
        elements_ = std::make_shared<const DeviceElements>(*compute_, mesh);
    return elements_;
}

void DeviceScene::updateLights(const DeviceSceneInputs& inputs) {
    uploadLights(inputs);
}

void DeviceScene::uploadLights(const DeviceSceneInputs& inputs) {
    ComputeContext& compute = *compute_;
    faceMaterials = DeviceArray<FaceMaterial>::upload(
        compute, rad::faceMaterials(inputs.mesh, inputs.patchShadingColour ? *inputs.patchShadingColour : inputs.patchReflectance,
                                    inputs.patchEmission), "faces' materials");
    const PunctualLightSet& punctual = inputs.lights.punctual;
    const SurfaceLightTable& surfaces = inputs.lights.surfaces;
    punctualLights = DeviceArray<PunctualLight>::upload(compute, punctual.lights, "punctual lights");
    lightTree = DeviceArray<LightNode>::upload(compute, punctual.tree, "punctual lights' tree");
    surfaceLights =
        DeviceArray<SurfaceLight>::upload(compute, surfaces.lights, "emitting patches sampled for direct light");
    surfaceLightEnds = DeviceArray<rad_uint>::upload(compute, surfaces.ends, "emitting patches' sampling table");
    lightOfPatch = DeviceArray<rad_uint>::upload(compute, surfaces.lightOfPatch, "emitting patches' lights");
    info_.punctualCount = static_cast<rad_uint>(punctual.lights.size());
    info_.directional = punctual.directional;
    info_.surfaceLightCount = static_cast<rad_uint>(surfaces.lights.size());
    info = DeviceArray<SceneInfo>::upload(compute, {info_}, "scene's description");
}

cl::Program& DeviceScene::program(const std::string& file, bool followSpecular) const {
    std::string options = masked_ ? "-DRAD_ALPHA_MASKS" : "";
    if (specularFaces_ && followSpecular) options += options.empty() ? "-DRAD_SPECULAR_TRANSPORT" : " -DRAD_SPECULAR_TRANSPORT";
    if (ggxTable_) options += options.empty() ? "-DRAD_GGX_TABLE" : " -DRAD_GGX_TABLE";
    if (layered_) options += " -DRAD_LAYERS";
    if (normalMapped_) options += options.empty() ? "-DRAD_NORMAL_MAPS" : " -DRAD_NORMAL_MAPS";
    return compute_->program(file, options);
}

cl_uint DeviceScene::bindScene(cl::Kernel& kernel) const {
    cl_uint index = 0;
    RAD_SCENE_ARGS(RAD_HOST_BIND)
    return index;
}

std::vector<std::string> DeviceScene::argumentNames() {
    return {RAD_SCENE_ARGS(RAD_HOST_NAME)};
}

std::uint64_t DeviceScene::bytes() const {
    std::uint64_t sum = 0;
#define RAD_DEVICE_SCENE_BYTES(kind, type, name) sum += name.bytes();
    RAD_SCENE_ARGS(RAD_DEVICE_SCENE_BYTES)
#undef RAD_DEVICE_SCENE_BYTES
    return sum;
}

}  // namespace rad
