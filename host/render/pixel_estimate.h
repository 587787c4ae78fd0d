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

#include "cl/device_array.h"
#include "cl/kernel_pack.h"
#include "render/image.h"

namespace rad {

struct PixelEstimate {
    Image image;                  // mean radiance per pixel, W / m^2 / sr
    std::vector<float> variance;  // per pixel, the variance of its mean's luminance (samples' spread / n)
    std::uint64_t rays = 0;       // rays traced in all
    std::uint32_t samples = 0;    // per pixel
};

// The per-pixel sums and ray counts a sampling kernel writes (its arguments `sums` and `rays`),
// made before the work so that a device that cannot hold them refuses first.
struct PixelSums {
    PixelSums(ComputeContext& compute, int width, int height, const std::string& what);
    DeviceArray<rad_float4> sums;
    DeviceArray<rad_uint> rays;
};

// Samples `samples` per pixel of a width x height image: launch(first, count) runs the kernel,
// whose other arguments are bound, for the samples first .. first + count - 1 of every pixel,
// writing into `out`. `what` names the work in messages.
PixelEstimate estimatePixels(const PixelSums& out, int width, int height, std::uint32_t samples,
                             const std::function<void(std::uint32_t first, std::uint32_t count)>& launch,
                             const std::string& what);

// The same for a kernel whose pack has the fields sums, rays, firstSample and sampleCount (the
// path tracer's, the camera pass's): those are set here, the rest of `args` by the caller.
template <typename Args>
PixelEstimate estimatePixels(DeviceKernel<Args>& kernel, Args& args, const PixelSums& out, int width, int height,
                             std::uint32_t samples, const std::string& what) {
    args.sums = out.sums;
    args.rays = out.rays;
    const std::size_t pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    return estimatePixels(
        out, width, height, samples,
        [&](std::uint32_t first, std::uint32_t count) {
            args.firstSample = first;
            args.sampleCount = count;
            kernel.launch(args, pixels);
        },
        what + " " + std::to_string(width) + " x " + std::to_string(height));
}

}  // namespace rad
