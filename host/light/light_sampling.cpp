#include "light/light_sampling.h"

#include "cl/buffers.h"
#include "util/shares.h"

static_assert(sizeof(SurfaceLight) == 32, "SurfaceLight must match the kernels' layout");

namespace rad {

SurfaceLightTable surfaceLightTable(const PreparedScene& scene) {
    const Mesh& mesh = scene.mesh();
    const DeviceScene& device = scene.device();
    SurfaceLightTable table;
    std::vector<double> power;
    for (const DirectSource& source : scene.emitters().directSources()) {
        const std::uint32_t face = mesh.patches.at(source.triangle).face;
        if (device.textured && device.faceTextures.at(face).emissiveSlot >= 0) continue;
        // Alpha-masked: rays pass through its clear texels, which a point drawn on the whole
        // triangle would light from; rays that hit it find its light instead.
        const int material = mesh.faces.at(face).material;
        if (scene.scene().materials.at(static_cast<std::size_t>(material)).alphaMode == Material::AlphaMode::Mask)
            continue;
        const glm::vec3& le = source.radiance;
        const double weight = (static_cast<double>(le.x) + le.y + le.z) * source.area;
        if (!(weight > 0.0)) continue;
        if (table.lightOfPatch.empty()) table.lightOfPatch.assign(mesh.patches.size(), 0);
        SurfaceLight light{};
        light.radiance[0] = le.x;
        light.radiance[1] = le.y;
        light.radiance[2] = le.z;
        light.triangle = source.triangle;
        table.lights.push_back(light);
        table.lightOfPatch[source.triangle] = static_cast<std::uint32_t>(table.lights.size());
        power.push_back(weight);
    }
    appendShares(power.data(), power.size(), table.ends);
    return table;
}

DeviceSurfaceLights uploadSurfaceLights(ComputeContext& compute, const SurfaceLightTable& table) {
    DeviceSurfaceLights device;
    device.count = static_cast<cl_uint>(table.lights.size());
    std::vector<SurfaceLight> lights = table.lights;
    std::vector<std::uint32_t> ends = table.ends, lightOfPatch = table.lightOfPatch;
    if (lights.empty()) lights.resize(1);
    if (ends.empty()) ends.resize(1);
    if (lightOfPatch.empty()) lightOfPatch.resize(1);
    device.lights = uploadBuffer(compute, lights, "emitting patches sampled for direct light");
    device.ends = uploadBuffer(compute, ends, "emitting patches' sampling table");
    device.lightOfPatch = uploadBuffer(compute, lightOfPatch, "emitting patches' lights");
    return device;
}

DeviceLightSampling uploadLightSampling(const PreparedScene& scene, bool surfaces) {
    ComputeContext& compute = scene.compute();
    DeviceLightSampling out;
    PunctualLightSet set = scene.emitters().punctualLights();
    out.punctualCount = static_cast<cl_uint>(set.lights.size());
    out.directional = static_cast<cl_uint>(set.directional);
    if (set.lights.empty()) set.lights.resize(1);  // OpenCL buffers may not be empty
    if (set.tree.empty()) set.tree.resize(1);
    out.punctual = uploadBuffer(compute, set.lights, "punctual lights");
    out.tree = uploadBuffer(compute, set.tree, "punctual lights' tree");
    out.surfaces = uploadSurfaceLights(compute, surfaces ? surfaceLightTable(scene) : SurfaceLightTable{});
    return out;
}

}  // namespace rad
