#pragma once
// The reference path tracer (kernels/pathtrace.cl): a diffuse-only, unbiased Monte Carlo image
// of the scene through the same BVH, independent of the patches, to measure radiosity images
// against. A reference, not a renderer: no light sampling, so it needs many samples.

#include <cstdint>

#include "prepared/prepared_scene.h"
#include "render/image.h"
#include "render/view.h"

namespace rad {

struct PathTraceOptions {
    int width = 256, height = 256;
    std::uint32_t samples = 64;     // paths per pixel
    std::uint32_t maxBounces = 0;   // 0: no limit (Russian roulette ends paths); 1: direct light only
    std::uint32_t seed = 1;
};

struct PathTraceResult {
    Image image;                    // mean radiance per pixel, W / m^2 / sr
    std::uint64_t rays = 0;         // rays traced in all
};

// Reflectance and emission come from each face's patches (the face's material); the image
// depends only on the scene, the view and the options, not on the patch size.
PathTraceResult pathTrace(const PreparedScene& scene, const View& view, const PathTraceOptions& options);

}  // namespace rad
