#pragma once
// What a path of kernels/view_path.h reads of the solution, on the device: the light arriving at
// the elements' welded vertices (and, in direct mode, the indirect part of it gathered per
// element, and with mirrors or glass the part that came by way of them), with the element trees
// to find them. The scene's materials and lights are the device scene's. The camera pass's
// direct and final-gather modes and the lightmap's texels (lightmap/texel_bake.h) both bind it
// after the scene's arrays (kernels/kernel_args.h: RAD_VIEW_SOLUTION_ARGS), so a pixel and a
// texel showing the same point read the same light; one command makes it once for both.

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "cl/device_array.h"
#include "device/device_elements.h"
#include "device/kernel_arguments.h"
#include "mesh/elements.h"
#include "mesh/vertices.h"
#include "prepared/prepared_scene.h"

namespace rad {

enum class RenderMode;

// What the paths read of the solution and how they treat it.
struct ViewPathSolution {
    const ElementMesh& elements;
    const DeviceElements& deviceElements;
    const MeshVertices& vertices;
    // The light H arriving at each element (Solution::irradiance), W / m^2: what a gather ray
    // reads where it lands (kernels/view_path.h: solution_reflected).
    const std::vector<glm::vec3>& elementIrradiance;
    // Where the solve carried light through mirrors and glass (Solution::causticIrradiance): the
    // part of H that came by way of them, at each vertex of `vertices`, which the surfaces a path
    // shades read interpolated; empty: the paths find it by cosine rays through them.
    const std::vector<glm::vec3>& vertexCaustic;
};

// The mode argument kernels/view_path.h reads: RAD_VIEW_DIRECT or RAD_VIEW_FINAL_GATHER.
rad_uint viewPathMode(RenderMode mode);

class ViewPathInputs {
public:
    // Refuses inconsistent sizes (InputError). `direct`: some path will be taken in direct mode,
    // which reads the solution's indirect light per element, gathered first here
    // (`indirectRaysPerElement` cosine rays each, keyed by `seed`).
    ViewPathInputs(const PreparedScene& scene, const ViewPathSolution& solution, bool direct,
                   std::uint32_t indirectRaysPerElement, std::uint32_t seed);

    // The pack a path kernel takes after the scene's.
    const ViewSolutionArgs& arguments() const { return arguments_; }
    bool direct() const { return direct_; }

private:
    DeviceArray<rad_uint4> corners_;
    DeviceArray<rad_float4> irradiance_, indirect_, caustic_;
    ViewSolutionArgs arguments_;
    bool direct_ = false;
};

}  // namespace rad
