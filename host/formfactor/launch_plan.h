#pragma once
// Splitting ray requests into kernel launches of bounded size. A request that straddles two
// launches continues its sample sequence in the second (firstSample), so the split changes
// nothing in the result.

#include <cstdint>
#include <vector>

#include "shared_types.h"

namespace rad {

struct RayRequest {
    std::uint32_t firstTriangle = 0;  // in DeviceScene::triangles
    std::uint32_t triangleCount = 1;  // > 1: sample the run of triangles by area
    std::uint32_t guide = 0;          // with triangleCount > 1: where the run's guide starts in the area tables
    std::uint64_t rays = 0;         // at most 2^32 - firstSample
    std::uint32_t firstSample = 0;
    std::uint32_t scramble = 0;
    std::uint32_t row = 0;
};

struct Launch {
    std::vector<RaySource> sources;
    std::uint32_t rayCount = 0;
};

// Launches of at most maxRays rays each, covering every request in order.
std::vector<Launch> planLaunches(const std::vector<RayRequest>& requests, std::uint32_t maxRays);

}  // namespace rad
