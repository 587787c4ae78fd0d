// Splitting ray requests into launches keeps every ray and continues each sample sequence.

#include <gtest/gtest.h>

#include "formfactor/launch_plan.h"

namespace rad {
namespace {

TEST(LaunchPlan, SplitsRequestsAndContinuesSequences) {
    std::vector<RayRequest> requests(3);
    requests[0].rays = 10;
    requests[0].row = 0;
    requests[1].rays = 25;
    requests[1].row = 1;
    requests[1].firstSample = 100;
    requests[2].rays = 1;
    requests[2].row = 2;
    const auto launches = planLaunches(requests, 8);
    std::vector<std::uint64_t> rays(3, 0), nextSample{0, 100, 0};
    std::uint64_t total = 0;
    for (const Launch& launch : launches) {
        EXPECT_LE(launch.rayCount, 8u);
        std::uint32_t next = 0;
        for (const RaySource& s : launch.sources) {
            EXPECT_EQ(s.firstRay, next);  // consecutive within the launch
            next += s.rayCount;
            EXPECT_EQ(s.firstSample, nextSample[s.row]);
            nextSample[s.row] += s.rayCount;
            rays[s.row] += s.rayCount;
        }
        EXPECT_EQ(next, launch.rayCount);
        total += launch.rayCount;
    }
    EXPECT_EQ(rays, (std::vector<std::uint64_t>{10, 25, 1}));
    EXPECT_EQ(total, 36u);
    EXPECT_EQ(launches.size(), 5u);  // ceil(36 / 8)
}

}  // namespace
}  // namespace rad
