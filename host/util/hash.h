#pragma once
// The kernels' integer hash (kernels/rng.h), for keys the host derives from the user's seed.

#include <cstdint>

namespace rad {

constexpr std::uint32_t hash32(std::uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}

constexpr std::uint32_t hash32(std::uint32_t a, std::uint32_t b) { return hash32(a ^ hash32(b + 0x9e3779b9u)); }

}  // namespace rad
