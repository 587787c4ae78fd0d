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

// The bits of a guide to `count` shares (shareGuide): ceil(log2(count)), at most 16; as
// kernels/sampling.h's guide_bits.
inline unsigned guideBits(std::size_t count) {
    unsigned bits = 0;
    while (bits < 16 && (std::size_t{1} << bits) < count) ++bits;
    return bits;
}

// The guide to the `count` shares `ends` (Chen and Asau's cutpoints), as kernels/sampling.h's
// pick_guided reads it: 2^guideBits(count) entries, entry j the share that the j-th of as many
// equal parts of 2^32 starts in (empty for no shares). The share a coordinate falls on then lies
// between its part's entry and the next part's, most often the same or the next share, where a
// search of all the ends takes log2(count) dependent steps.
inline std::vector<std::uint32_t> shareGuide(const std::uint32_t* ends, std::size_t count) {
    if (count == 0) return {};
    const unsigned bits = guideBits(count);
    std::vector<std::uint32_t> guide(std::size_t{1} << bits);
    for (std::size_t j = 0; j < guide.size(); ++j) {
        const std::uint64_t start = static_cast<std::uint64_t>(j) << (32 - bits);
        // the first share whose end lies past the part's start (the last one's end is 2^32)
        const std::uint32_t* past =
            std::upper_bound(ends, ends + (count - 1), start, [](std::uint64_t s, std::uint32_t e) { return s < e; });
        guide[j] = static_cast<std::uint32_t>(past - ends);
    }
    return guide;
}

// Share k of the `count` shares `ends`, as a probability.
inline double shareOf(const std::uint32_t* ends, std::size_t count, std::size_t k) {
    const double start = k == 0 ? 0.0 : ends[k - 1];
    const double end = k + 1 == count ? 4294967296.0 : ends[k];
    return (end - start) / 4294967296.0;
}

}  // namespace rad
