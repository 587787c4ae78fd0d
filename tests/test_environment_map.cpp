// The environment map on the host (scene/environment_map.h, light/environment_light.h): reading
// OpenEXR maps and refusing bad ones, Blender's mapping with glTF +Y up, the sampling density,
// and the emitter's power and samples. The device's twins are in test_environment.cpp.

#include <cmath>
#include <random>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "light/environment_light.h"
#include "scene/environment_map.h"
#include "scene/gltf_loader.h"
#include "shared_math.h"
#include "test_support.h"
#include "util/error.h"

namespace rad {
namespace {

std::string mapPath(const std::string& name) {
    return test::sourcePath("tests/data/environment/" + name);
}

// The distance between two coordinates across the image, which wraps.
double acrossDistance(double a, double b) {
    const double d = std::fabs(a - b);
    return std::min(d, 1.0 - d);
}

TEST(EnvironmentMap, MapsDirectionsAsBlendersEnvironmentTextureWithGltfYUp) {
    // The image's centre column looks along +X, its quarter column along Blender's +Y (glTF -Z),
    // its top row straight up.
    EXPECT_NEAR(environmentCoordinates({1, 0, 0}).x, 0.5, 1e-15);
    EXPECT_NEAR(environmentCoordinates({1, 0, 0}).y, 0.5, 1e-15);
    EXPECT_NEAR(environmentCoordinates({0, 0, -1}).x, 0.25, 1e-15);
    EXPECT_NEAR(environmentCoordinates({0, 0, 1}).x, 0.75, 1e-15);
    EXPECT_NEAR(acrossDistance(environmentCoordinates({-1, 0, 0}).x, 0.0), 0.0, 1e-15);
    EXPECT_NEAR(environmentCoordinates({0, 1, 0}).y, 0.0, 1e-15);
    EXPECT_NEAR(environmentCoordinates({0, -1, 0}).y, 1.0, 1e-15);
    // Cycles' own formula (direction_to_equirectangular): u = 0.5 - atan2(b.y, b.x) / 2 pi,
    // v = 1 - acos(b.z) / pi with v up the image, for Blender's b = (x, -z, y).
    std::mt19937 rng(3);
    std::normal_distribution<double> g;
    for (int i = 0; i < 1000; ++i) {
        const glm::dvec3 d = glm::normalize(glm::dvec3(g(rng), g(rng), g(rng)));
        const glm::dvec3 b(d.x, -d.z, d.y);
        const double u = 0.5 - std::atan2(b.y, b.x) / (2.0 * kPi), v = 1.0 - std::acos(b.z) / kPi;
        const glm::dvec2 ut = environmentCoordinates(d);
        EXPECT_NEAR(acrossDistance(ut.x, u), 0.0, 1e-12);
        EXPECT_NEAR(ut.y, 1.0 - v, 1e-12);
        EXPECT_NEAR(glm::length(environmentDirection(ut.x, ut.y) - d), 0.0, 1e-12);
    }
}

TEST(EnvironmentMap, ReadsRgbAndGreyMapsTimesTheStrength) {
    const EnvironmentMap rgb = loadEnvironmentMap(mapPath("uniform.exr"), 2.5);
    EXPECT_EQ(rgb.width, 8);
    EXPECT_EQ(rgb.height, 4);
    for (const glm::vec3& texel : rgb.radiance) EXPECT_EQ(texel, glm::vec3(2.5f));
    const EnvironmentMap grey = loadEnvironmentMap(mapPath("grey-y.exr"), 1.0);
    ASSERT_EQ(grey.radiance.size(), 8u);
    for (const glm::vec3& texel : grey.radiance) EXPECT_EQ(texel, glm::vec3(0.5f));
    // Row 0 is the top: the sun test map's sun is in rows 8 and 9.
    const EnvironmentMap sun = loadEnvironmentMap(mapPath("sun.exr"), 1.0);
    EXPECT_EQ(sun.at(47, 8), glm::vec3(2000.0f));
    EXPECT_EQ(sun.at(0, 0), glm::vec3(0.1f));
    EXPECT_EQ(sun.at(0, 31), glm::vec3(0.0f));
}

TEST(EnvironmentMap, RefusesBadMapsNamingTheFileAndTheProblem) {
    const std::pair<const char*, const char*> cases[] = {
        {"bad-negative.exr", "texel (1, 0) is not a radiance"},
        {"bad-nan.exr", "texel (0, 1) is not a radiance"},
        {"bad-black.exr", "black everywhere"},
        {"bad-no-colour.exr", "neither R, G and B channels nor a Y channel"},
        {"bad-luminance-chroma.exr", "luminance and chroma"},
        {"bad-not-exr.exr", "cannot read the environment map as OpenEXR"},
        {"bad-truncated.exr", "cannot read the environment map as OpenEXR"},
        {"no-such-map.exr", "cannot open the environment map"},
    };
    for (const auto& [name, problem] : cases) {
        try {
            loadEnvironmentMap(mapPath(name), 1.0);
            ADD_FAILURE() << name << " was read";
        } catch (const FileError& e) {
            EXPECT_EQ(e.path(), mapPath(name));
            EXPECT_NE(e.problem().find(problem), std::string::npos) << e.what();
        }
    }
    // A strength that overflows single precision is refused, not turned into infinities.
    EXPECT_THROW(loadEnvironmentMap(mapPath("sun.exr"), 1e36), FileError);
}

TEST(EnvironmentMap, SamplingDensityIntegratesToOneAndFollowsTheLight) {
    const EnvironmentMap map = loadEnvironmentMap(mapPath("sun.exr"), 1.0);
    const EnvironmentSampling sampling = environmentSampling(map);
    // The density is constant within a texel: its sum over texel centres times their solid
    // angles is its integral.
    double integral = 0.0;
    for (int y = 0; y < map.height; ++y)
        for (int x = 0; x < map.width; ++x)
            integral +=
                environmentPdf(map, sampling, environmentDirection((x + 0.5) / map.width, (y + 0.5) / map.height)) *
                environmentTexelSolidAngle(map, y);
    EXPECT_NEAR(integral, 1.0, 1e-8);
    const auto pdfAt = [&](int x, int y) {
        return environmentPdf(map, sampling, environmentDirection((x + 0.5) / map.width, (y + 0.5) / map.height));
    };
    // In one row texels are drawn in proportion to the largest radiance their filter blends:
    // the sun's 2000 against the sky's 0.1 far from it. A sky texel's share is about 5e4 of the
    // 2^32 units, so rounding its two ends may move the ratio by 2e-5 of itself.
    EXPECT_NEAR(pdfAt(47, 8) / pdfAt(10, 8), 20000.0, 20000.0 * 4e-5);
    EXPECT_NEAR(pdfAt(46, 9) / pdfAt(10, 9), 20000.0, 20000.0 * 4e-5);  // the filter's reach
    // The ground, black with no light within the filter's reach, is never drawn.
    EXPECT_EQ(pdfAt(10, 20), 0.0);
    EXPECT_GT(pdfAt(10, 16), 0.0);  // the ground's first row blends the sky's last
}

TEST(EnvironmentLight, PowerIsWhatEntersTheBoundingSphereAndSamplesAverageToIt) {
    Scene scene = loadGltf(mapPath("plane.gltf"));
    const double radius = 0.5 * scene.bounds().diagonal();
    scene.environment = std::make_shared<const EnvironmentMap>(loadEnvironmentMap(mapPath("uniform.exr"), 1.0));
    // A uniform L enters a sphere of radius R with pi R^2 x 4 pi L.
    const double power = kPi * radius * radius * 4.0 * kPi;
    EXPECT_NEAR(EnvironmentLight::find(scene)->power().x, power, 1e-8 * power);

    scene.environment = std::make_shared<const EnvironmentMap>(loadEnvironmentMap(mapPath("sun.exr"), 1.0));
    const auto light = EnvironmentLight::find(scene);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const int n = 200000;
    double sum = 0.0, squares = 0.0;
    for (int i = 0; i < n; ++i) {
        const EmissionSample s = light->sample(glm::dvec4(u(rng), u(rng), u(rng), u(rng)));
        ASSERT_NEAR(glm::length(s.direction), 1.0, 1e-9);
        // The sample starts on the bounding sphere's disk facing it and travels into it.
        const glm::dvec3 toCentre = -s.position;  // the plane's bounding box is centred on 0
        ASSERT_GT(glm::dot(toCentre, s.direction), 0.0);
        sum += s.power.x;
        squares += s.power.x * s.power.x;
    }
    const double mean = sum / n, sigma = std::sqrt((squares / n - mean * mean) / n);
    EXPECT_NEAR(mean, light->power().x, 5.0 * sigma);
    EXPECT_GT(sigma, 0.0);
}

}  // namespace
}  // namespace rad
