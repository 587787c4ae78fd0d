#include "solver/ray_hit_checks.h"

#include <cmath>

#include "util/format.h"

namespace rad {

double relativeNoise(const std::vector<ReceiverNoise>& receivers) {
    double area = 0.0, light = 0.0, squares = 0.0;
    for (const ReceiverNoise& r : receivers) {
        area += r.area;
        light += r.area * r.radiosity;
        squares += r.area * r.noise * r.noise;
    }
    if (!(light > 0.0)) return 0.0;
    return std::sqrt(squares / area) / (light / area);
}

std::vector<std::string> rayHitWarnings(const std::vector<ReceiverNoise>& receivers, std::size_t elements,
                                        std::size_t patches, std::uint64_t rays) {
    if (receivers.empty() || rays == 0) return {};
    const double noise = relativeNoise(receivers);
    if (!(noise > kNoiseToWarn)) return {};
    double area = 0.0, dark = 0.0;
    for (const ReceiverNoise& r : receivers) {
        area += r.area;
        if (!r.hit) dark += r.area;
    }
    const bool split = elements > patches;
    // The noise falls as 1 / sqrt(rays): the rays for half the noise the warning allows.
    const double target = 0.5 * kNoiseToWarn;
    const double needed = std::ceil(static_cast<double>(rays) * (noise / target) * (noise / target));
    return {format("shoot: the %s values carry about %.0f %% noise (RMS over the reflecting area, of its mean "
                   "radiosity; %.0f %% of that area got no ray hit); use --rays %.3g or more (now %llu) for about "
                   "%.0f %%, or a larger %s",
                   split ? "element" : "patch", 100.0 * noise, 100.0 * dark / area, needed,
                   static_cast<unsigned long long>(rays), 100.0 * target,
                   split ? "--element-size (or fewer refinements)" : "--patch-size")};
}

}  // namespace rad
