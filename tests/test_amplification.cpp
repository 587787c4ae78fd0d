// The measured amplification of a progressive solve (solver/amplification.h): the return
// ratio from the solve's totals, the power per ray, and the overshoot, in closed form.

#include <gtest/gtest.h>

#include <limits>

#include "solver/amplification.h"

namespace rad {
namespace {

UnshotPartial partialHolding(const glm::dvec3& unshot) {
    UnshotPartial p{};
    for (int c = 0; c < 3; ++c) p.sums[c] = static_cast<float>(unshot[c]);
    return p;
}

Shooter shotOf(const glm::dvec3& power) {
    Shooter s{};
    for (int c = 0; c < 3; ++c) s.taken[c] = static_cast<float>(power[c]);
    return s;
}

// A closed room of one reflectance rho: E to shoot, S shot, the rest returned as unshot power.
Amplification room(double rho, double maxRho, double shot, double threshold = Amplification::kThreshold,
                   bool overshoot = true) {
    Amplification flow(glm::dvec3(1.0), glm::dvec3(6.0 * rho), glm::dvec3(maxRho), glm::dvec3(0.0), threshold,
                       overshoot);
    flow.addShot(shotOf(glm::dvec3(shot)));
    flow.update({partialHolding(glm::dvec3(1.0 - shot + rho * shot))});
    return flow;
}

TEST(Amplification, NothingShotIsNoGain) {
    const Amplification flow(glm::dvec3(1.0), glm::dvec3(6.0), glm::dvec3(1.0), glm::dvec3(0.0));
    EXPECT_EQ(flow.returnRatio(0), 0.0);
    EXPECT_EQ(flow.gain(0), 1.0);
    EXPECT_EQ(flow.rayPowerScale(), 1.0);
    EXPECT_EQ(flow.overshoot(), glm::vec3(0.0f));
}

TEST(Amplification, TheReturnRatioIsWhatCameBackOfWhatWasShot) {
    // 1 W per channel to shoot, 10 W shot, 0.9 W unshot now: 9.9 W came back, r = 0.99, G = 100.
    // One reflectance (rho_max = r): rays carry 25 times the power; the unshot 0.9 W will bring
    // 0.9 x 0.99 / 0.01 = 89.1 W of reflected light, spread over rho A = 6 x 0.99 m^2.
    const Amplification flow = room(0.99, 0.99, 10.0);
    EXPECT_NEAR(flow.returnRatio(0), 0.99, 1e-6);
    EXPECT_NEAR(flow.gain(1), 100.0, 1e-3);
    EXPECT_TRUE(flow.large());
    EXPECT_NEAR(flow.rayPowerScale(), 25.0, 1e-2);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(flow.overshoot()[c], 0.9 * 0.99 / 0.01 / (6.0 * 0.99), 1e-3);
    EXPECT_NEAR(flow.shot().x, 10.0, 1e-6);
}

TEST(Amplification, NotMeasuredUntilTwiceTheLightWasShot) {
    // The first bounce alone says little (a lamp aimed at a white ceiling over a dark floor).
    const Amplification early = room(0.99, 0.99, 1.5);
    EXPECT_FALSE(early.measured(0));
    EXPECT_FALSE(early.large());
    EXPECT_EQ(early.overshoot(), glm::vec3(0.0f));
    EXPECT_EQ(early.rayPowerScale(), 1.0);
    EXPECT_TRUE(room(0.99, 0.99, 2.0).measured(0));
}

TEST(Amplification, ModestGainChangesNothing) {
    // r = 0.5: G = 2, below the threshold: rays as before, no overshoot.
    const Amplification flow = room(0.5, 0.5, 4.0);
    EXPECT_NEAR(flow.gain(0), 2.0, 1e-9);
    EXPECT_FALSE(flow.large());
    EXPECT_EQ(flow.rayPowerScale(), 1.0);
    EXPECT_EQ(flow.overshoot(), glm::vec3(0.0f));
}

TEST(Amplification, RaysCarryMoreOnlyWhereTheLevelIsNotNoisier) {
    // r = 0.9 with surfaces up to 0.99 (some light lost to darker ones or escaping): the level's
    // variance bound 0.9 x 0.09 x G = 0.81 already exceeds a gain-4 scene's 0.75: no scaling.
    EXPECT_EQ(room(0.9, 0.99, 5.0).rayPowerScale(), 1.0);
    // r = 0.9 with rho_max = 0.92: bound 0.9 x 0.02 x 10 = 0.18; 0.75 / 0.18 = 4.2 > G / 4 = 2.5.
    EXPECT_NEAR(room(0.9, 0.92, 5.0).rayPowerScale(), 2.5, 1e-6);
    // ... and r = 0.9 with rho_max = 0.95: 0.75 / (0.9 x 0.05 x 10) = 1.67.
    EXPECT_NEAR(room(0.9, 0.95, 5.0).rayPowerScale(), 0.75 / (0.9 * 0.05 * 10.0), 1e-6);
    // The overshoot is the gain's alone.
    EXPECT_TRUE(room(0.9, 0.99, 5.0).large());
    EXPECT_GT(room(0.9, 0.99, 5.0).overshoot().x, 0.0f);
}

TEST(Amplification, ChannelsOvershootByTheirOwnGain) {
    // Red returns 0.95 of what is shot, blue 0.5: red overshoots, blue (G = 2) does not, and the
    // rays keep their power (blue allows no more).
    Amplification flow(glm::dvec3(1.0), glm::dvec3(2.0, 2.0, 1.0), glm::dvec3(0.95, 0.95, 0.5), glm::dvec3(0.0));
    flow.addShot(shotOf(glm::dvec3(10.0, 10.0, 2.0)));
    flow.update({partialHolding(glm::dvec3(0.5, 0.5, 0.0))});  // came back: 9.5, 9.5, 1
    ASSERT_TRUE(flow.large());
    EXPECT_NEAR(flow.overshoot().x, 0.5 * 0.95 / 0.05 / 2.0, 1e-4);
    EXPECT_EQ(flow.overshoot().z, 0.0f);
    EXPECT_EQ(flow.rayPowerScale(), 1.0);
}

TEST(Amplification, AnInfiniteThresholdOrSplitPatchesNeverOvershoot) {
    const Amplification never = room(0.99, 0.99, 10.0, std::numeric_limits<double>::infinity());
    EXPECT_FALSE(never.large());
    EXPECT_EQ(never.rayPowerScale(), 1.0);
    EXPECT_EQ(never.overshoot(), glm::vec3(0.0f));
    const Amplification elements = room(0.99, 0.99, 10.0, Amplification::kThreshold, false);
    EXPECT_TRUE(elements.large());
    EXPECT_EQ(elements.overshoot(), glm::vec3(0.0f));
    EXPECT_NEAR(elements.rayPowerScale(), 25.0, 1e-2);  // the rays' power does not depend on elements
}

}  // namespace
}  // namespace rad
