#include "light/direct_light_kernels.h"

#include <algorithm>
#include <cmath>

#include "device/kernel_arguments.h"
#include "mesh/patch_textures.h"
#include "mesh/sampling_tables.h"

namespace rad {

std::vector<DirectLightElement> directLightElements(const Mesh& mesh, const ElementMesh& elements) {
    std::vector<DirectLightElement> out;
    out.reserve(elements.elements().size());
    for (const Element& element : elements.elements()) {
        const Patch& patch = mesh.patches[element.patch];
        DirectLightElement record{};
        float largest = 0.0f;
        for (const glm::vec3& v : patch.p)
            largest = std::max({largest, std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
        for (std::size_t k = 0; k < 3; ++k)
            for (int c = 0; c < 3; ++c) record.corners[k][c] = element.p[k][c];
        for (int c = 0; c < 3; ++c) record.normal[c] = patch.normal[c];
        record.normal[3] = originLift(largest);
        // Where the corners lie in their face, for its alpha mask, and which face it is.
        const Face& face = mesh.faces[patch.face];
        for (std::size_t k = 0; k < 3; ++k) {
            const glm::dvec2 w = barycentric(glm::dvec3(element.p[k]), glm::dvec3(face.p[0]), glm::dvec3(face.p[1]),
                                             glm::dvec3(face.p[2]));
            record.faceWeights[k][0] = static_cast<float>(w.x);
            record.faceWeights[k][1] = static_cast<float>(w.y);
        }
        record.face = patch.face;
        record.blackBack = face.backPatch == kNoPatch ? 1 : 0;
        out.push_back(record);
    }
    return out;
}

void addFrontsAndBacks(const ElementMesh& elements, const std::vector<rad_float4>& out, std::size_t stride,
                       const glm::dvec3& scale, const glm::dvec3& power, DirectLight& light) {
    glm::dvec3 arrived(0.0), backs(0.0);
    const std::size_t count = elements.elements().size();
    auto rgb = [&](std::size_t i) { return glm::dvec3(out[i].s[0], out[i].s[1], out[i].s[2]); };
    for (std::size_t e = 0; e < count; ++e) {
        const double area = elements.elements()[e].area;
        const glm::dvec3 front = area * rgb(stride * e) * scale;
        const glm::dvec3 back = area * rgb(stride * e + 1) * scale;
        light.arrived[e] += front;
        arrived += front;
        backs += back;
        if (stride < 3) continue;
        const glm::dvec3 bySpecular = area * rgb(stride * e + 2) * scale;
        if (bySpecular == glm::dvec3(0.0)) continue;
        if (light.arrivedBySpecular.empty()) light.arrivedBySpecular.assign(count, glm::dvec3(0.0));
        light.arrivedBySpecular[e] += bySpecular;
    }
    light.absorbedByBacks += backs;
    light.escaped += power - arrived - backs;
}

void addEnvironmentDirectLight(const PreparedScene& scene, const ElementMesh& elements, std::uint32_t raysPerSide,
                               std::uint32_t key, SpecularModel model, const glm::dvec3& scale,
                               const glm::dvec3& power, DirectLight& light) {
    const std::size_t count = elements.elements().size();
    if (count == 0) return;
    ComputeContext& compute = scene.compute();
    const DeviceArray<DirectLightElement> layout = DeviceArray<DirectLightElement>::upload(
        compute, directLightElements(scene.mesh(), elements), "light from outside: elements");
    const DeviceArray<rad_float4> out =
        DeviceArray<rad_float4>::allocate(compute, 3 * count, "light from outside", DeviceAccess::write);
    DeviceKernel<EnvironmentDirectArgs> kernel = scene.device().kernel<EnvironmentDirectArgs>(
        {"direct_light.cl", model == SpecularModel::follow}, "environment_direct");
    EnvironmentDirectArgs args;
    args.elements = layout;
    args.rays = raysPerSide;
    args.key = key;
    args.out = out;
    launchOverElements(kernel, args, count, 2.0 * raysPerSide);
    addFrontsAndBacks(elements, out.read(), 3, scale, power, light);
}

}  // namespace rad
