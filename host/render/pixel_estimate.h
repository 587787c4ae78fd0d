#pragma once
// Images made of Monte Carlo samples per pixel (the path tracer, the camera pass's direct and
// final-gather modes): the kernel runs in launches of a few samples per pixel, each writing per
// pixel its samples' radiance summed and the sum of their luminances' squares, and the host adds
// the launches in double. The launches depend only on the image size and the sample count, so
// the image does not depend on threads or work-group sizes, and on the device only through float
// rounding.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "cl/device_array.h"
#include "cl/kernel_pack.h"
#include "render/image.h"

namespace rad {

struct PixelEstimate {
    Image image;                  // mean radiance per pixel, W / m^2 / sr
    std::vector<float> variance;  // per pixel, the variance of its mean's luminance (samples' spread / n)
    std::uint64_t rays = 0;       // rays traced in all
    std::uint32_t samples = 0;    // per pixel
    // The image's relative noise: the root of the pixels' mean variance over their mean luminance
    // (imageNoise); 0 for one sample per pixel or a black image.
    double noise = 0.0;
};

// How far a set of pixels' means may be from their expectations, relative to the image: the root
// of the mean of their luminances' variances over the mean luminance. What a noise target stops
// at; 0 where the image is black.
double imageNoise(const std::vector<glm::dvec3>& sums, const std::vector<double>& squares, std::uint32_t samples);

// When to stop sampling: after `samples` per pixel, or sooner, once the image's noise is at most
// `noise` (0: no target) with at least kLeastSamplesForNoise per pixel (the noise's own estimate
// needs them). The check comes after each launch, whose sizes depend only on the image size, so
// where sampling stops depends only on the seed and the scene.
constexpr std::uint32_t kLeastSamplesForNoise = 16;
struct SampleBudget {
    std::uint32_t samples = 1;
    double noise = 0.0;
};

// The per-pixel sums and ray counts a sampling kernel writes (its arguments `sums` and `rays`),
// made before the work so that a device that cannot hold them refuses first.
struct PixelSums {
    PixelSums(ComputeContext& compute, int width, int height, const std::string& what);
    DeviceArray<rad_float4> sums;
    DeviceArray<rad_uint> rays;
};

// Samples up to budget.samples per pixel of a width x height image (SampleBudget says when it
// stops sooner): launch(first, count) runs the kernel, whose other arguments are bound, for the
// samples first .. first + count - 1 of every pixel, writing into `out`. `what` names the work in
// messages.
PixelEstimate estimatePixels(const PixelSums& out, int width, int height, SampleBudget budget,
                             const std::function<void(std::uint32_t first, std::uint32_t count)>& launch,
                             const std::string& what);

// The same for a kernel whose pack has the fields sums, rays, firstSample and sampleCount (the
// path tracer's, the camera pass's): those are set here, the rest of `args` by the caller.
template <typename Args>
PixelEstimate estimatePixels(DeviceKernel<Args>& kernel, Args& args, const PixelSums& out, int width, int height,
                             SampleBudget budget, const std::string& what) {
    args.sums = out.sums;
    args.rays = out.rays;
    const std::size_t pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    return estimatePixels(
        out, width, height, budget,
        [&](std::uint32_t first, std::uint32_t count) {
            args.firstSample = first;
            args.sampleCount = count;
            kernel.launch(args, pixels);
        },
        what + " " + std::to_string(width) + " x " + std::to_string(height));
}

}  // namespace rad
