#include "render/pixel_estimate.h"

#include <algorithm>
#include <cmath>

#include <glm/vec3.hpp>

#include "util/error.h"

namespace rad {
namespace {

// Samples per launch, about: enough to keep a GPU busy, few enough that a launch stays short.
// It depends on the image size alone, so the sums (and the image) do not depend on the device.
constexpr std::uint64_t kSamplesPerLaunch = 1u << 20;
// The most samples one work item (one pixel) takes in a launch. Without it a tiny image would
// put up to kSamplesPerLaunch samples in one work item: one launch long enough for a GPU's
// watchdog to kill, a float sum of a million terms in the kernel, and a ray count that could
// overflow its 32 bits. It is small because Mesa's llvmpipe (rusticl) silently ends a work
// item's loops after 65,535 iterations in all (docs/results.md): 256 samples of a path or a
// gather, each a few rays of tens to hundreds of traversal steps, went past that and came back
// five times too dark; 16 stay well under it. A constant, so the launches (and the image)
// still depend only on the image size, the seed and the sample count. Images of 65,536 pixels
// or more never reach it.
constexpr std::uint64_t kMaxSamplesPerLaunch = 16;

// A pixel's mean over n samples from their sum and the sum of their luminances' squares: its
// luminance, and the variance of that mean (the samples' unbiased spread over n; 0 for one).
struct PixelMoments {
    glm::dvec3 mean;
    double luminance = 0.0, variance = 0.0;
};
PixelMoments pixelMoments(const glm::dvec3& sum, double squares, double n) {
    PixelMoments m;
    m.mean = sum / n;
    m.luminance = 0.2126 * m.mean.x + 0.7152 * m.mean.y + 0.0722 * m.mean.z;
    if (n > 1.0) m.variance = std::max(0.0, squares - n * m.luminance * m.luminance) / ((n - 1.0) * n);
    return m;
}

}  // namespace

PixelSums::PixelSums(ComputeContext& compute, int width, int height, const std::string& what)
    : sums(DeviceArray<rad_float4>::allocate(compute, static_cast<std::size_t>(width) * static_cast<std::size_t>(height),
                                            what + "'s sums", DeviceAccess::write)),
      rays(DeviceArray<rad_uint>::allocate(compute, static_cast<std::size_t>(width) * static_cast<std::size_t>(height),
                                          what + "'s ray counts", DeviceAccess::write)) {}

double imageNoise(const std::vector<glm::dvec3>& sums, const std::vector<double>& squares, std::uint32_t samples) {
    if (samples < 2 || sums.empty()) return 0.0;
    double variance = 0.0, brightness = 0.0;
    for (std::size_t i = 0; i < sums.size(); ++i) {
        const PixelMoments m = pixelMoments(sums[i], squares[i], samples);
        variance += m.variance;
        brightness += m.luminance;
    }
    return brightness > 0.0 ? std::sqrt(variance / static_cast<double>(sums.size())) /
                                  (brightness / static_cast<double>(sums.size()))
                            : 0.0;
}

PixelEstimate estimatePixels(const PixelSums& out, int width, int height, SampleBudget budget,
                             const std::function<void(std::uint32_t first, std::uint32_t count)>& launch,
                             const std::string& what) {
    std::uint32_t samples = budget.samples;
    if (samples < 1 || width < 1 || height < 1) throw InputError(what + ": no samples or no pixels to estimate");
    const std::size_t pixels = static_cast<std::size_t>(width) * height;
    const std::uint64_t mostPerLaunch = std::min<std::uint64_t>(kMaxSamplesPerLaunch, samples);
    const auto perLaunch =
        static_cast<std::uint32_t>(std::clamp<std::uint64_t>(kSamplesPerLaunch / pixels, 1, mostPerLaunch));
    std::vector<glm::dvec3> sum(pixels, glm::dvec3(0.0));
    std::vector<double> squares(pixels, 0.0);
    std::vector<rad_float4> part(pixels);
    std::vector<rad_uint> rays(pixels);
    PixelEstimate result;
    for (std::uint32_t first = 0; first < samples; first += perLaunch) {
        const std::uint32_t count = std::min(perLaunch, samples - first);
        launch(first, count);
        out.sums.enqueueRead(part);
        rays = out.rays.read(pixels);
        for (std::size_t i = 0; i < pixels; ++i) {
            sum[i] += glm::dvec3(part[i].s[0], part[i].s[1], part[i].s[2]);
            squares[i] += part[i].s[3];
            result.rays += rays[i];
        }
        const std::uint32_t taken = first + count;
        if (budget.noise > 0.0 && taken >= kLeastSamplesForNoise && taken < samples &&
            imageNoise(sum, squares, taken) <= budget.noise)
            samples = taken;  // the target is met: stop here
    }
    result.samples = samples;
    result.noise = imageNoise(sum, squares, samples);
    result.image.width = width;
    result.image.height = height;
    result.image.pixels.resize(pixels);
    result.variance.resize(pixels);
    for (std::size_t i = 0; i < pixels; ++i) {
        const PixelMoments m = pixelMoments(sum[i], squares[i], samples);
        result.image.pixels[i] = glm::vec3(m.mean);
        result.variance[i] = static_cast<float>(m.variance);
    }
    return result;
}

}  // namespace rad
