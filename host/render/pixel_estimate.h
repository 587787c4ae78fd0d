#pragma once
// Images made of Monte Carlo samples per pixel (the path tracer, the camera pass's direct and
// final-gather modes): the kernel runs in launches of a few samples per pixel, each writing per
// pixel its samples' radiance summed and the sum of their luminances' squares, and the host adds
// the launches in double. The launches depend only on the image size and the sample count, so
// the image does not depend on threads or work-group sizes, and on the device only through float
// rounding.

#include <cstdint>
#include <string>
#include <vector>

#include "cl/compute_context.h"
#include "cl/opencl.h"
#include "render/image.h"

namespace rad {

struct PixelEstimate {
    Image image;                  // mean radiance per pixel, W / m^2 / sr
    std::vector<float> variance;  // per pixel, the variance of its mean's luminance (samples' spread / n)
    std::uint64_t rays = 0;       // rays traced in all
    std::uint32_t samples = 0;    // per pixel
};

// Runs `kernel`, whose other arguments are bound, for `samples` samples per pixel of a
// width x height image: the launch's first sample and sample count go to arguments
// firstSampleArgument and firstSampleArgument + 1, the sums and ray counts the kernel writes to
// arguments sumsArgument and sumsArgument + 1. `what` names the work in device errors.
PixelEstimate estimatePixels(ComputeContext& compute, cl::Kernel& kernel, cl_uint firstSampleArgument,
                             cl_uint sumsArgument, int width, int height, std::uint32_t samples,
                             const std::string& what);

}  // namespace rad
