#include "render/renderer.h"

#include "device/kernel_arguments.h"
#include "util/error.h"

namespace rad {
namespace {

std::vector<rad_float4> float4s(const std::vector<glm::vec3>& values) {
    std::vector<rad_float4> out(values.size());
    for (std::size_t i = 0; i < values.size(); ++i) out[i] = {{values[i].x, values[i].y, values[i].z, 0.0f}};
    return out;
}

}  // namespace

PixelGrid pixelGrid(int samples) {
    if (samples < 1) throw InputError("the camera pass needs at least one sample per pixel");
    PixelGrid grid;
    for (int down = 1; static_cast<long long>(down) * down <= samples; ++down)
        if (samples % down == 0) grid.down = down;
    grid.across = samples / grid.down;
    return grid;
}

std::vector<rad_uint4> elementCorners(const MeshVertices& vertices) {
    std::vector<rad_uint4> corners(vertices.corners.size());
    for (std::size_t e = 0; e < corners.size(); ++e)
        corners[e] = {{vertices.corners[e][0], vertices.corners[e][1], vertices.corners[e][2], 0}};
    return corners;
}

Image renderView(const PreparedScene& scene, const DeviceElements& elements, const MeshVertices& vertices,
                 const std::vector<glm::vec3>& vertexRadiance, const View& view, const RenderOptions& options,
                 const std::vector<glm::vec3>* vertexIrradiance) {
    ComputeContext& compute = scene.compute();
    if (options.width < 1 || options.height < 1 || options.width > 16384 || options.height > 16384)
        throw InputError("image size " + std::to_string(options.width) + " x " + std::to_string(options.height) +
                         " is outside 1..16384 on each side");
    const std::size_t pixels = static_cast<std::size_t>(options.width) * options.height;
    // Textured faces are shown as Le(uv) + rho(uv) H / pi where the irradiance H is given.
    const bool textured = vertexIrradiance != nullptr && scene.device().textured();
    const DeviceArray<rad_float4> image =
        DeviceArray<rad_float4>::allocate(compute, pixels, "image", DeviceAccess::write);
    const DeviceArray<rad_uint4> corners =
        DeviceArray<rad_uint4>::upload(compute, elementCorners(vertices), "element corners");
    const DeviceArray<rad_float4> radiance =
        DeviceArray<rad_float4>::upload(compute, float4s(vertexRadiance), "vertex radiance");
    const DeviceArray<rad_float4> irradiance = DeviceArray<rad_float4>::upload(
        compute, textured ? float4s(*vertexIrradiance) : std::vector<rad_float4>{}, "vertex irradiance");
    RenderArgs args;
    args.elements = elements.nodes;
    args.corners = corners;
    args.vertexRadiance = radiance;
    args.vertexIrradiance = irradiance;
    args.showTextures = textured ? 1 : 0;
    args.camera = cameraRays(view, options.width, options.height);
    args.width = static_cast<rad_uint>(options.width);
    args.height = static_cast<rad_uint>(options.height);
    const PixelGrid grid = pixelGrid(options.samples);
    args.samplesAcross = static_cast<rad_uint>(grid.across);
    args.samplesDown = static_cast<rad_uint>(grid.down);
    args.wireframe = options.wireframe ? 1 : 0;
    args.image = image;
    scene.device().kernel<RenderArgs>("render.cl", "render").launch(args, pixels);
    const std::vector<rad_float4> out = image.read();
    Image result;
    result.width = options.width;
    result.height = options.height;
    result.pixels.resize(pixels);
    for (std::size_t i = 0; i < pixels; ++i) result.pixels[i] = {out[i].s[0], out[i].s[1], out[i].s[2]};
    return result;
}

}  // namespace rad
