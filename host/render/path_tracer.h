#pragma once
// The reference path tracer (kernels/pathtrace.cl): an unbiased Monte Carlo image of the scene
// (diffuse surfaces, and ideal mirrors and glass: scene/material_model.h) through the same BVH, independent of the
// patches, to measure radiosity images against. Emitting surfaces, punctual lights and environment maps are sampled at
// every bounce (with multiple importance sampling where rays can also find the light).

#include <cstdint>

#include "prepared/prepared_scene.h"
#include "render/image.h"
#include "render/pixel_estimate.h"
#include "render/view.h"

namespace rad {

struct PathTraceOptions {
    int width = 256, height = 256;
    std::uint32_t samples = 64;     // paths per pixel, at most
    double noise = 0.0;             // stop sooner at this image noise (SampleBudget); 0: none
    std::uint32_t maxBounces = 0;   // 0: no limit (Russian roulette ends paths); 1: direct light only
    std::uint32_t seed = 1;
    // Sample emitting surfaces at every bounce (surface_lights.h); off, only the paths that hit
    // an emitter find its light: the same image in the mean, far noisier with small emitters.
    bool lightSampling = true;
};

using PathTraceResult = PixelEstimate;

// Reflectance and emission come from each face's patches (the face's material); the image
// depends only on the scene, the view and the options, not on the patch size.
PathTraceResult pathTrace(const PreparedScene& scene, const View& view, const PathTraceOptions& options);

}  // namespace rad
