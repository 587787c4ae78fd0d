#pragma once
// What the camera pass's sampled modes and the path tracer sample for direct light, on the
// device: the punctual lights with their tree (light/light_tree.h), and the emitting patches
// (below).
//
// The emitting patches the camera pass and the path tracer sample for direct light
// (kernels/surface_lights.h): each with its emitted radiance and area, a table that picks one in
// proportion to its power, and per patch which light it is, so a ray drawn otherwise that hits
// it can be weighed against the light samples (multiple importance sampling). Patches whose face
// has an emissive texture are left out (their light varies within the patch, which the light
// samples, at the patch's mean radiance, would not follow), and so are alpha-masked ones (rays
// pass through their clear texels, where a light sample would find light): rays find their light
// where they hit them.

#include <cstdint>
#include <vector>

#include "cl/opencl.h"
#include "prepared/prepared_scene.h"
#include "shared_types.h"

namespace rad {

struct SurfaceLightTable {
    std::vector<SurfaceLight> lights;
    std::vector<std::uint32_t> ends;          // shares of 2^32 by power (util/shares.h)
    std::vector<std::uint32_t> lightOfPatch;  // per patch: 1 + its light, or 0 (empty: no lights)
};

SurfaceLightTable surfaceLightTable(const PreparedScene& scene);

// The table on the device, as a kernel's (lights, ends, lightOfPatch, count) arguments; empty
// tables upload one placeholder entry each, since OpenCL buffers may not be empty.
struct DeviceSurfaceLights {
    cl::Buffer lights, ends, lightOfPatch;
    cl_uint count = 0;
};
DeviceSurfaceLights uploadSurfaceLights(ComputeContext& compute, const SurfaceLightTable& table);

// Both kinds on the device; `surfaces` false: no emitting patch is listed (count 0).
struct DeviceLightSampling {
    cl::Buffer punctual, tree;  // PunctualLight and LightNode records (a placeholder each when empty)
    cl_uint punctualCount = 0, directional = 0;
    DeviceSurfaceLights surfaces;
};
DeviceLightSampling uploadLightSampling(const PreparedScene& scene, bool surfaces);

}  // namespace rad
