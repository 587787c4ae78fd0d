#include "render/view_pass.h"

#include <algorithm>
#include <iterator>

#include "device/kernel_arguments.h"
#include "render/view_path_inputs.h"
#include "util/error.h"

namespace rad {

std::string renderModeName(RenderMode mode) {
    switch (mode) {
        case RenderMode::radiosity:
            return "radiosity";
        case RenderMode::direct:
            return "direct";
        case RenderMode::finalGather:
            return "final-gather";
    }
    return "radiosity";
}

std::optional<RenderMode> renderModeNamed(const std::string& name) {
    for (RenderMode m : {RenderMode::radiosity, RenderMode::direct, RenderMode::finalGather})
        if (renderModeName(m) == name) return m;
    return std::nullopt;
}

namespace {

void checkImage(const ViewPassOptions& options) {
    if (options.width < 1 || options.height < 1 || options.width > 16384 || options.height > 16384)
        throw InputError("image size " + std::to_string(options.width) + " x " + std::to_string(options.height) +
                         " is outside 1..16384 on each side");
    if (options.samples < 1) throw InputError("the camera pass needs at least one sample per pixel");
    if (options.mode == RenderMode::radiosity)
        throw InputError("renderViewPass draws the direct and final-gather modes; radiosity is renderView's");
}

std::string passName(const ViewPassOptions& options) {
    return "the " + renderModeName(options.mode) + " camera pass";
}

PixelEstimate runViewPass(const PreparedScene& scene, const ViewPathInputs& inputs, const View& view,
                          const ViewPassOptions& options, const PixelSums& out) {
    if (options.mode == RenderMode::direct && !inputs.direct())
        throw InputError("the direct camera pass needs the solution's indirect light per element");
    DeviceKernel<ViewPassArgs> kernel =
        scene.device().kernel<ViewPassArgs>("view_pass.cl", "view_pass", inputs.arguments());
    ViewPassArgs args;
    args.camera = cameraRays(view, options.width, options.height);
    args.width = static_cast<rad_uint>(options.width);
    args.height = static_cast<rad_uint>(options.height);
    args.mode = viewPathMode(options.mode);
    args.seed = options.seed;
    args.near = static_cast<float>(options.nearPatches * scene.mesh().patchSize);
    return estimatePixels(kernel, args, out, options.width, options.height, {options.samples, options.noise},
                          passName(options));
}

}  // namespace

PixelEstimate renderViewPass(const PreparedScene& scene, const ElementMesh& elements,
                             const DeviceElements& deviceElements, const MeshVertices& vertices,
                             const std::vector<glm::vec3>& elementIrradiance, const View& view,
                             const ViewPassOptions& options, const std::vector<glm::vec3>& vertexCaustic) {
    checkImage(options);
    // The pixels' sums first, so that a device that cannot hold them refuses before any work.
    const PixelSums out(scene.compute(), options.width, options.height, passName(options));
    const ViewPathInputs inputs(scene, {elements, deviceElements, vertices, elementIrradiance, vertexCaustic},
                                options.mode == RenderMode::direct, options.indirectRaysPerElement, options.seed);
    return runViewPass(scene, inputs, view, options, out);
}

PixelSums viewPassSums(const PreparedScene& scene, const ViewPassOptions& options) {
    checkImage(options);
    return PixelSums(scene.compute(), options.width, options.height, passName(options));
}

PixelEstimate renderViewPass(const PreparedScene& scene, const ViewPathInputs& inputs, const View& view,
                             const ViewPassOptions& options, const PixelSums& sums) {
    return runViewPass(scene, inputs, view, options, sums);
}

PixelEstimate renderViewPass(const PreparedScene& scene, const ViewPathInputs& inputs, const View& view,
                             const ViewPassOptions& options) {
    return runViewPass(scene, inputs, view, options, viewPassSums(scene, options));
}

}  // namespace rad
