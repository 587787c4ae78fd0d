#pragma once
// What a path of kernels/view_path.h reads, on the device: the solution as light arriving at the
// elements' welded vertices (and, in direct mode, the indirect part of it gathered per element),
// the faces' materials and the lights. The camera pass's direct and final-gather modes and the
// lightmap's texels (lightmap/texel_bake.h) both bind these as the first arguments after the
// scene's, so a pixel and a texel showing the same point read the same light.

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "cl/opencl.h"
#include "light/light_sampling.h"
#include "mesh/device_elements.h"
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
    // The light H arriving at each vertex, W / m^2.
    const std::vector<glm::vec3>& vertexIrradiance;
    // Where the solve carried light through mirrors and glass (Solution::causticIrradiance): the
    // part of H that came by way of them; empty: the paths find it by cosine rays through them.
    const std::vector<glm::vec3>& vertexCaustic;
};

// The mode argument kernels/view_path.h reads: RAD_VIEW_DIRECT or RAD_VIEW_FINAL_GATHER.
cl_uint viewPathMode(RenderMode mode);

class ViewPathInputs {
public:
    // Refuses inconsistent sizes (InputError). Direct mode first gathers the solution's indirect
    // light per element (`indirectRaysPerElement` cosine rays each, keyed by `seed`).
    ViewPathInputs(const PreparedScene& scene, const ViewPathSolution& solution, RenderMode mode,
                   std::uint32_t indirectRaysPerElement, std::uint32_t seed);

    // The device memory these take, in all and in the largest buffer, for a reservation made
    // before uploading them.
    struct Bytes {
        std::uint64_t total = 0, largest = 0;
    };
    static Bytes deviceBytes(const PreparedScene& scene, const ViewPathSolution& solution, RenderMode mode);

    // Binds them to `kernel` from the argument after the scene's buffers (DeviceScene::kArguments)
    // on, as kernels/view_path.h's RAD_VIEW_PATH_PARAMS lists them (23: elements ... the
    // environment's columns); returns the next argument's index.
    cl_uint bind(const PreparedScene& scene, cl::Kernel& kernel) const;

private:
    const DeviceElements& deviceElements_;
    cl::Buffer corners_, irradiance_, indirect_, caustic_;
    cl::Buffer reflectance_, emission_, faceTextures_, srgb_;
    cl_uint textured_ = 0, caustics_ = 0;
    DeviceLightSampling lights_;
};

}  // namespace rad
