#pragma once
// Tables that pick one of many parts in proportion to a weight, as the kernels' pick_share and
// share_of read them (kernels/sampling.h): the ends of shares of 2^32, the last end (2^32)
// implied. Integer ends, so a part's probability is the same number on the host and every device.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace rad {

// Appends the ends of `count` shares in proportion to `weights` (uniform when they sum to zero).
inline void appendShares(const double* weights, std::size_t count, std::vector<std::uint32_t>& ends) {
    double total = 0.0;
    for (std::size_t k = 0; k < count; ++k) total += weights[k];
    double running = 0.0;
    std::uint32_t previous = 0;
    for (std::size_t k = 0; k < count; ++k) {
        running += total > 0.0 ? weights[k] : 1.0;
        const double fraction = running / (total > 0.0 ? total : static_cast<double>(count));
        const double end = std::floor(4294967296.0 * fraction + 0.5);
        previous = std::max(previous, static_cast<std::uint32_t>(std::min(end, 4294967295.0)));
        ends.push_back(previous);
    }
}

// Share k of the `count` shares `ends`, as a probability.
inline double shareOf(const std::uint32_t* ends, std::size_t count, std::size_t k) {
    const double start = k == 0 ? 0.0 : ends[k - 1];
    const double end = k + 1 == count ? 4294967296.0 : ends[k];
    return (end - start) / 4294967296.0;
}

}  // namespace rad
