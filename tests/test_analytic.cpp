// The analytic references the estimators are judged against.

#include <cmath>

#include <gtest/gtest.h>

#include "util/analytic_form_factors.h"

namespace rad {
namespace {

std::vector<glm::dvec3> square(double y, bool down) {
    std::vector<glm::dvec3> s{{0, y, 0}, {0, y, 1}, {1, y, 1}, {1, y, 0}};
    if (down) std::reverse(s.begin(), s.end());
    return s;
}

TEST(Analytic, ClosedFormsMatchPublishedValues) {
    EXPECT_NEAR(parallelSquaresFactor(1.0, 1.0), 0.199825, 1e-6);
    EXPECT_NEAR(perpendicularSquaresFactor(), 0.200044, 1e-6);
    EXPECT_NEAR(coaxialDisksFactor(1.0, 1.0, 1.0), 0.381966, 1e-6);
}

TEST(Analytic, ContourIntegralMatchesClosedForm) {
    EXPECT_NEAR(polygonToPolygonFactor(square(0, false), square(1, true)), parallelSquaresFactor(1.0, 1.0), 1e-9);
    // A 256-gon is close to the disk (the difference shrinks like 1/n^2).
    std::vector<glm::dvec3> lower, upper;
    for (int k = 0; k < 256; ++k) {
        const double a = 2 * M_PI * k / 256;
        lower.push_back({std::cos(a), 0, std::sin(a)});
        upper.push_back({std::cos(a), 1, std::sin(a)});
    }
    EXPECT_NEAR(polygonToPolygonFactor(lower, upper), coaxialDisksFactor(1, 1, 1), 2e-4);
}

TEST(Analytic, PointToPolygon) {
    // A unit square centred 1 m above a point facing it: 4 x the corner formula.
    const std::vector<glm::dvec3> s{{-0.5, -0.5, 1}, {0.5, -0.5, 1}, {0.5, 0.5, 1}, {-0.5, 0.5, 1}};
    const double a = 0.5 / std::sqrt(1.25);
    const double expected = 4.0 * (2.0 * a * std::atan(a)) / (2.0 * M_PI);
    EXPECT_NEAR(pointToPolygonFactor({0, 0, 0}, {0, 0, 1}, s), expected, 1e-12);
    // A polygon spanning the whole hemisphere in the limit: a huge square gives F -> 1.
    const std::vector<glm::dvec3> big{{-1e4, -1e4, 1}, {1e4, -1e4, 1}, {1e4, 1e4, 1}, {-1e4, 1e4, 1}};
    EXPECT_NEAR(pointToPolygonFactor({0, 0, 0}, {0, 0, 1}, big), 1.0, 1e-4);
}

}  // namespace
}  // namespace rad
