#pragma once
// The camera pass's modes (README, "Rendering"): how the image is made from the solution.
//   radiosity:    the solution interpolated over the elements (render/renderer.h): fast, and as
//                 good as the mesh; shadows and emitters' outlines are as sharp as the elements.
//   direct:       per pixel, the light straight from the emitters by light sampling
//                 (kernels/view_pass.cl), plus the solution's indirect light interpolated over
//                 the elements: sharp shadows without the mesh, where the indirect light is smooth.
//   final-gather: per pixel, the direct light as above, plus the indirect light gathered by a
//                 cosine ray from the hit that reads the solution where it lands.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "device/device_elements.h"
#include "mesh/elements.h"
#include "mesh/vertices.h"
#include "prepared/prepared_scene.h"
#include "render/pixel_estimate.h"
#include "render/view.h"
#include "render/view_path_inputs.h"

namespace rad {

enum class RenderMode { radiosity, direct, finalGather };

// "radiosity", "direct", "final-gather".
std::string renderModeName(RenderMode mode);
// The mode of that name, or nothing.
std::optional<RenderMode> renderModeNamed(const std::string& name);

struct ViewPassOptions {
    int width = 512, height = 512;
    std::uint32_t samples = 16;                 // per pixel, at most
    double noise = 0.0;                         // stop sooner at this image noise (SampleBudget); 0: none
    RenderMode mode = RenderMode::finalGather;  // direct or finalGather
    std::uint32_t seed = 1;
    // Final gather: a gather ray that lands closer than this many patch sizes takes one more
    // diffuse bounce before it reads the solution (kernels/view_pass.cl says why).
    double nearPatches = 4.0;
    // Direct mode: cosine rays per element that gather its indirect light from the solution.
    std::uint32_t indirectRaysPerElement = 256;
};

// The solution is read as elementIrradiance: the light H arriving at each element of `elements`,
// W / m^2. vertexCaustic, where the solve carried light through mirrors and glass
// (Solution::causticIrradiance): the part of H that came by way of them, at each vertex of
// `vertices` (made from `elements`), which the pass then reads at the surfaces it shades instead
// of finding it with cosine rays through them (kernels/view_pass.cl); empty: the pass finds it by
// those rays.
PixelEstimate renderViewPass(const PreparedScene& scene, const ElementMesh& elements,
                             const DeviceElements& deviceElements, const MeshVertices& vertices,
                             const std::vector<glm::vec3>& elementIrradiance, const View& view,
                             const ViewPassOptions& options, const std::vector<glm::vec3>& vertexCaustic = {});

// The same from the solution already on the device (render/view_path_inputs.h), which the
// lightmap may share; it holds the indirect light per element where options.mode is direct.
PixelEstimate renderViewPass(const PreparedScene& scene, const ViewPathInputs& inputs, const View& view,
                             const ViewPassOptions& options);

// The pixels' sums on the device, made before the inputs where those take work to make (the
// direct mode's gather), so that a device that cannot hold the image refuses first; the image's
// size is checked too. The pass then writes into them.
PixelSums viewPassSums(const PreparedScene& scene, const ViewPassOptions& options);
PixelEstimate renderViewPass(const PreparedScene& scene, const ViewPathInputs& inputs, const View& view,
                             const ViewPassOptions& options, const PixelSums& sums);

}  // namespace rad
