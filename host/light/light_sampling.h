#pragma once
// The emitting patches the camera pass and the path tracer sample for direct light
// (kernels/surface_lights.h): each with its emitted radiance and area, a table that picks one in
// proportion to its power, and per patch which light it is, so a ray drawn otherwise that hits
// it can be weighed against the light samples (multiple importance sampling). Patches whose face
// has an emissive texture are left out (their light varies within the patch, which the light
// samples, at the patch's mean radiance, would not follow), and so are alpha-masked ones (rays
// pass through their clear texels, where a light sample would find light): rays find their light
// where they hit them. The device scene uploads the table (device/device_scene.h) with the
// punctual lights and their tree (light/light_tree.h).

#include <cstdint>
#include <vector>

#include "shared_types.h"

namespace rad {

class Emitters;
struct Mesh;
struct Scene;

struct SurfaceLightTable {
    std::vector<SurfaceLight> lights;
    // Shares of 2^32 by power, one per light, then their guide (util/shares.h: shareGuide).
    std::vector<std::uint32_t> ends;
    std::vector<std::uint32_t> lightOfPatch;  // per patch: 1 + its light, or 0 (empty: no lights)
};

SurfaceLightTable surfaceLightTable(const Scene& scene, const Mesh& mesh, const Emitters& emitters);

}  // namespace rad
