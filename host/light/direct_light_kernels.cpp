#include "light/direct_light_kernels.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "cl/buffers.h"
#include "cl/error.h"
#include "mesh/patch_textures.h"
#include "mesh/sampling_tables.h"

namespace rad {

std::vector<cl_float4> directLightElements(const Mesh& mesh, const ElementMesh& elements) {
    std::vector<cl_float4> out;
    out.reserve(kDirectLightElementStride * elements.elements().size());
    for (const Element& element : elements.elements()) {
        const Patch& patch = mesh.patches[element.patch];
        const bool blackBack = mesh.faces[patch.face].backPatch == kNoPatch;
        float largest = 0.0f;
        for (const glm::vec3& v : patch.p)
            largest = std::max({largest, std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
        for (std::size_t k = 0; k < 3; ++k) {
            const glm::vec3& p = element.p[k];
            out.push_back({{p.x, p.y, p.z, k == 0 && blackBack ? 1.0f : 0.0f}});
        }
        out.push_back({{patch.normal.x, patch.normal.y, patch.normal.z, originLift(largest)}});
        // Where the corners lie in their face, for its alpha mask, and which face it is.
        const Face& face = mesh.faces[patch.face];
        glm::dvec2 w[3];
        for (std::size_t k = 0; k < 3; ++k)
            w[k] = barycentric(glm::dvec3(element.p[k]), glm::dvec3(face.p[0]), glm::dvec3(face.p[1]),
                               glm::dvec3(face.p[2]));
        cl_uint faceIndex = patch.face;
        float faceBits = 0.0f;
        std::memcpy(&faceBits, &faceIndex, sizeof faceBits);
        out.push_back({{static_cast<float>(w[0].x), static_cast<float>(w[0].y), static_cast<float>(w[1].x),
                        static_cast<float>(w[1].y)}});
        out.push_back({{static_cast<float>(w[2].x), static_cast<float>(w[2].y), faceBits, 0.0f}});
    }
    return out;
}

void launchOverElements(const PreparedScene& scene, const std::string& programFile, const std::string& kernelName,
                        const std::vector<cl_float4>& elements, double raysPerElement, const std::string& what,
                        const std::function<void(cl::Kernel&, cl_uint nextArgument)>& bind, SpecularModel model) {
    ComputeContext& compute = scene.compute();
    const std::size_t count = elements.size() / kDirectLightElementStride;
    if (count == 0) return;
    try {
        cl::Buffer elementBuffer = uploadBuffer(compute, elements, what + ": elements");
        cl::Kernel kernel = scene.device().kernel(
            scene.device().program(compute, programFile, model == SpecularModel::follow), kernelName.c_str());
        setKernelArgs(kernel, DeviceScene::kArguments, elementBuffer, cl_uint{0}, static_cast<cl_uint>(count));
        bind(kernel, DeviceScene::kArguments + 3);
        // About 2^22 rays per launch: seconds at most on a CPU, far from a GPU's watchdog.
        const double perLaunch = std::max(1.0, std::floor(4194304.0 / std::max(raysPerElement, 1.0)));
        const auto step = static_cast<std::size_t>(std::min(perLaunch, 1048576.0));
        for (std::size_t first = 0; first < count; first += step) {
            kernel.setArg(DeviceScene::kArguments + 1, static_cast<cl_uint>(first));
            compute.launch(kernel, std::min(step, count - first));
        }
    } catch (const cl::Error& e) {
        throwDeviceError(e, what);
    }
}

void addFrontsAndBacks(const ElementMesh& elements, const std::vector<cl_float4>& out, std::size_t stride,
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

}  // namespace rad
