// The reference path tracer (render/path_tracer.h): the white furnace, a closed-form image
// mean, the bounce limit, and images that depend on the seed alone.
//
// Tolerances come from the estimator's own variance. Each test's comment derives the variance
// of one path's radiance for independent samples; the samples are Owen-scrambled Sobol points
// per pixel and depth, which are stratified and do better, so independent samples' variance is
// the conservative figure. Pixel values (and image means) are checked to 6 (and 5) standard
// deviations: a pass by chance, not a loose bound, and a real bias of that size fails.

#include <cmath>

#include <gtest/gtest.h>

#include "device_fixture.h"
#include "render/path_tracer.h"

namespace rad {
namespace {

using test::PreparedScene;
using test::sharedCompute;

constexpr double kPi = 3.14159265358979323846;

// One patch per face: the path tracer reads faces only.
constexpr double kWholeFaces = 10.0;

PathTraceResult trace(const PreparedScene& s, const View& view, const PathTraceOptions& options) {
    return pathTrace(sharedCompute(), s.scene, s.mesh, *s.device, view, options);
}

// From the centre of the unit cube, looking into a corner with a wide lens: every pixel sees
// a face (positions are relative to the scene's centre, which is the cube's).
View insideTheCube() {
    View v;
    v.position = glm::vec3(0.0f);
    v.forward = glm::normalize(glm::vec3(1.0f, 0.3f, 0.6f));
    v.right = glm::normalize(glm::cross(v.forward, glm::vec3(0, 1, 0)));
    v.up = glm::cross(v.right, v.forward);
    v.yfov = 1.6f;
    return v;
}

TEST(PathTracer, WhiteFurnaceIsEOverOneMinusRhoEverywhere) {
    // Every face emits E = 1 (Le = 1/pi) with rho = 0.5: L = E / (1 - rho) / pi = 2/pi.
    // A path gathers Le at each of its hits with weight rho^k for the first 3 reflections
    // (no roulette yet), then survives each further hit with q = rho = 0.5, its weight
    // unchanged (rho / q = 1): X = Le (1 + rho + rho^2 + rho^3 + rho^3 G), G geometric with
    // P(G >= m) = q^m. E[X] = Le (1.875 + 0.125 q / (1 - q)) = 2 Le and
    // Var X = Le^2 rho^6 q / (1 - q)^2 = Le^2 / 32.
    const PreparedScene s("tests/data/solve/white-furnace.gltf", kWholeFaces);
    PathTraceOptions o;
    o.width = 32;
    o.height = 32;
    o.samples = 64;
    const PathTraceResult r = trace(s, insideTheCube(), o);
    const double le = 1.0 / kPi, expected = 2.0 * le;
    const double sigmaPixel = le / std::sqrt(32.0 * o.samples);
    const double pixels = static_cast<double>(r.image.pixels.size());
    double mean = 0.0;
    for (const glm::vec3& p : r.image.pixels)
        for (int c = 0; c < 3; ++c) {
            ASSERT_NEAR(p[c], expected, 6.0 * sigmaPixel);
            mean += p[c] / (3.0 * pixels);
        }
    EXPECT_NEAR(mean, expected, 5.0 * sigmaPixel / std::sqrt(pixels));
    EXPECT_GT(r.rays, static_cast<std::uint64_t>(pixels) * o.samples * 4);  // at least 4 hits a path
}

TEST(PathTracer, BounceLimitCutsTheSeries) {
    // With at most K reflections and no roulette before the 4th, the furnace's paths are all
    // alike: X = Le (1 + rho + ... + rho^K), no variance at all.
    const PreparedScene s("tests/data/solve/white-furnace.gltf", kWholeFaces);
    PathTraceOptions o;
    o.width = 16;
    o.height = 16;
    o.samples = 4;
    for (std::uint32_t k : {1u, 2u, 3u}) {
        o.maxBounces = k;
        const PathTraceResult r = trace(s, insideTheCube(), o);
        double series = 0.0;
        for (std::uint32_t j = 0; j <= k; ++j) series += std::pow(0.5, j);
        for (const glm::vec3& p : r.image.pixels)
            for (int c = 0; c < 3; ++c) ASSERT_NEAR(p[c], series / kPi, 1e-6) << "bounces " << k;
    }
}

TEST(PathTracer, FacingSquaresImageMeanIsRhoTimesTheViewFactor) {
    // An orthographic camera between the facing squares looks straight down and sees exactly
    // the bottom square (rho = 0.5). The lamp above (Le = 1, rho = 0) is seen only by the
    // reflected ray, so a path's radiance is X = rho Le [its cosine ray hits the lamp]: over
    // the uniformly sampled square, E[X] = rho Le F(bottom -> top) = 0.5 x 0.19982490, and
    // Var X = rho^2 Le^2 F (1 - F).
    const PreparedScene s("scenes/facing-squares.gltf", kWholeFaces);
    View v;
    v.orthographic = true;
    v.halfHeight = 0.5f;
    v.position = glm::vec3(glm::dvec3(0.5, 0.5, 0.5) - s.scene.origin);
    v.forward = {0, -1, 0};
    v.right = {1, 0, 0};
    v.up = {0, 0, -1};
    PathTraceOptions o;
    o.width = 64;
    o.height = 64;
    o.samples = 32;
    const PathTraceResult r = trace(s, v, o);
    const double f = 0.19982490, expected = 0.5 * f;
    const double n = static_cast<double>(r.image.pixels.size()) * o.samples;
    const double sigmaMean = 0.5 * std::sqrt(f * (1.0 - f) / n);
    double mean = 0.0;
    for (const glm::vec3& p : r.image.pixels) mean += p.x / static_cast<double>(r.image.pixels.size());
    EXPECT_NEAR(mean, expected, 5.0 * sigmaMean);
    for (const glm::vec3& p : r.image.pixels) {
        EXPECT_EQ(p.x, p.y);  // grey: the same paths in every channel
        EXPECT_EQ(p.x, p.z);
    }
}

TEST(PathTracer, TheSeedAloneDecidesTheImage) {
    // Counter-based samples: another work-group size gives the same bits; another seed does not.
    const PreparedScene s("scenes/cornell-box.gltf", kWholeFaces);
    const View view = chooseView(s.scene, "");
    PathTraceOptions o;
    o.width = 24;
    o.height = 20;
    o.samples = 8;
    const PathTraceResult a = trace(s, view, o);
    sharedCompute().setWorkGroupSize(16);
    const PathTraceResult b = trace(s, view, o);
    sharedCompute().setWorkGroupSize(64);
    EXPECT_TRUE(a.image.pixels == b.image.pixels);
    EXPECT_EQ(a.rays, b.rays);
    o.seed = 2;
    const PathTraceResult c = trace(s, view, o);
    EXPECT_FALSE(a.image.pixels == c.image.pixels);
}

}  // namespace
}  // namespace rad
