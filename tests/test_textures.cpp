// Textures (scene/texture_sampling.h, mesh/patch_textures.h, kernels/texture.h): sRGB decoding,
// what a patch's reflectance and emission become, and the camera pass showing the texture at
// pixel resolution.

#include <cmath>

#include <gtest/gtest.h>

#include "device_fixture.h"
#include "mesh/vertices.h"
#include "render/renderer.h"
#include "render/view.h"
#include "scene/texture_sampling.h"
#include "shared_math.h"
#include "solver/progressive_solver.h"

namespace rad {
namespace {

using test::sharedCompute;
using test::TestScene;

TEST(Textures, SrgbDecodingIsTheStandardsCurve) {
    for (int i = 0; i < 256; ++i) {
        const double c = i / 255.0;
        const double linear = c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
        EXPECT_EQ(srgbToLinear(static_cast<std::uint8_t>(i)), static_cast<float>(linear)) << i;
    }
    EXPECT_EQ(srgbToLinear(0), 0.0f);
    EXPECT_EQ(srgbToLinear(255), 1.0f);
}

TEST(Textures, LoadedFromDataUrisAndFromGlbBufferViews) {
    for (const char* file : {"tests/data/textures/uniform-texture.gltf", "tests/data/textures/uniform-texture.glb"}) {
        const Scene scene = loadGltf(test::sourcePath(file));
        ASSERT_EQ(scene.images.size(), 1u) << file;
        EXPECT_EQ(scene.images[0].width, 4);
        EXPECT_EQ(scene.images[0].height, 4);
        ASSERT_TRUE(scene.materials[0].baseColorTexture.present()) << file;
        EXPECT_EQ(scene.surfaces[0].texCoords[0].size(), scene.surfaces[0].positions.size());
        EXPECT_TRUE(scene.surfaces[0].texCoords[1].empty());
        EXPECT_TRUE(scene.warnings.empty()) << scene.warnings[0];
    }
}

TEST(Textures, AUniformTextureGivesEveryPatchItsDecodedValueTimesTheFactor) {
    // 4 x 4 texels of sRGB 128 under baseColorFactor (1, 0.5, 0.25).
    const TestScene s("tests/data/textures/uniform-texture.gltf", 0.1);
    const float grey = srgbToLinear(128);
    EXPECT_NEAR(grey, 0.2158605f, 1e-7f);
    for (const glm::vec3& rho : s.patches().reflectance) {
        EXPECT_FLOAT_EQ(rho.x, grey);
        EXPECT_FLOAT_EQ(rho.y, 0.5f * grey);
        EXPECT_FLOAT_EQ(rho.z, 0.25f * grey);
    }
}

TEST(Textures, APatchsReflectanceIsTheTexturesMeanOverIt) {
    // A black-and-white checker (nearest, repeated 4 times across): the floor's mean is 0.5.
    // Each patch's mean is the midpoint rule with at least four points per texel it covers;
    // only points within half their spacing of a checker edge can be misjudged, so the
    // area-weighted mean over the floor is within 1% of 0.5, and patches wholly inside one
    // texel read exactly 0 or 1.
    const TestScene s("tests/data/textures/checker-floor.gltf", 0.05);
    const std::size_t floor = s.surface("floor");
    double sum = 0.0, area = 0.0;
    int pure = 0, mixed = 0;
    for (std::size_t p = 0; p < s.mesh().patches.size(); ++p) {
        if (s.mesh().patches[p].surface != floor) continue;
        const double rho = s.patches().reflectance[p].x;
        sum += rho * s.patches().area[p];
        area += s.patches().area[p];
        EXPECT_GE(rho, 0.0);
        EXPECT_LE(rho, 1.0);
        (rho == 0.0 || rho == 1.0 ? pure : mixed) += 1;
    }
    EXPECT_NEAR(sum / area, 0.5, 0.005);
    EXPECT_GT(pure, 100);  // patches 1/20 m across, texels 1/8 m: most lie inside one
    EXPECT_GT(mixed, 10);
}

TEST(Textures, AnEmissiveTextureScalesTheEmittedPower) {
    // Half of the unit lamp's emissive texture is black: it emits pi x 0.5 W per channel.
    const TestScene s("tests/data/textures/half-lit-lamp.gltf", 0.05);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(s.emitters().power()[c], 0.5 * kPi, 0.005 * kPi);
}

// The light of a solve as the camera pass reads it: radiance B / pi and irradiance H at the
// vertices.
struct Shaded {
    MeshVertices vertices;
    std::vector<glm::vec3> radiance, irradiance;
};

Shaded solveAndShade(const TestScene& s, std::uint64_t rays) {
    ProgressiveOptions options;
    options.rays = rays;
    const ProgressiveResult r = ProgressiveSolver(s, s.elements).solve(options);
    Shaded out{weldVertices(s.mesh(), s.elements), {}, {}};
    out.radiance = vertexValues(s.elements, out.vertices, r.radiosity);
    for (glm::vec3& v : out.radiance) v /= static_cast<float>(kPi);
    std::vector<glm::vec3> h(r.incident.size());
    for (std::size_t e = 0; e < h.size(); ++e) h[e] = r.incident[e] / s.elements.elements()[e].area;
    out.irradiance = vertexValues(s.elements, out.vertices, h);
    return out;
}

TEST(Textures, TheCameraPassShowsRhoOfUvTimesTheIrradiance) {
    // A uniform texture under a sky: rho(uv) is the patches' rho everywhere, so the textured
    // path, rho(uv) H / pi, shows what the plain path, B / pi, shows, to float rounding.
    Scene scene = loadGltf(test::sourcePath("tests/data/textures/uniform-texture.gltf"));
    scene.sky = glm::vec3(1.0f, 2.0f, 3.0f);
    const TestScene s(std::move(scene), 0.1);
    const Shaded shaded = solveAndShade(s, 100'000);
    const View view = chooseView(s.scene(), "");
    const DeviceElements elements(sharedCompute(), s.elements);
    const Image textured =
        renderView(s, elements, shaded.vertices, shaded.radiance, view, {48, 48, 1}, &shaded.irradiance);
    const Image plain = renderView(s, elements, shaded.vertices, shaded.radiance, view, {48, 48, 1});
    int floor = 0;
    for (std::size_t i = 0; i < plain.pixels.size(); ++i) {
        if (plain.pixels[i] == glm::vec3(1.0f, 2.0f, 3.0f)) continue;  // the sky
        ++floor;
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(textured.pixels[i][c], plain.pixels[i][c], 1e-5 * plain.pixels[i][c]) << i;
    }
    EXPECT_GT(floor, 100);
}

TEST(Textures, TheCameraPassShowsTheTextureAtPixelResolution) {
    // Straight down at the checker floor, 8 pixels per texel: pixels inside black texels are
    // exactly black, pixels inside white ones show H / pi, at least what the patch means show.
    const TestScene s("tests/data/textures/checker-floor.gltf", 0.05);
    const Shaded shaded = solveAndShade(s, 200'000);
    const View view = chooseView(s.scene(), "plan");
    const DeviceElements elements(sharedCompute(), s.elements);
    const int size = 64;
    const Image textured =
        renderView(s, elements, shaded.vertices, shaded.radiance, view, {size, size, 1}, &shaded.irradiance);
    const Image plain = renderView(s, elements, shaded.vertices, shaded.radiance, view, {size, size, 1});
    int black = 0, white = 0;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            if (x % 8 == 0 || x % 8 == 7 || y % 8 == 0 || y % 8 == 7) continue;  // near a texel edge
            const glm::vec3 t = textured.pixels[static_cast<std::size_t>(y * size + x)];
            const glm::vec3 p = plain.pixels[static_cast<std::size_t>(y * size + x)];
            if (t.x == 0.0f) {
                ++black;
                continue;
            }
            ++white;
            EXPECT_GE(t.x, p.x * (1.0f - 1e-5f)) << x << ", " << y;
            EXPECT_EQ(t.x, t.y);
        }
    // 8 x 8 texels, half of each colour, 36 inner pixels each.
    EXPECT_EQ(black, 32 * 36);
    EXPECT_EQ(white, 32 * 36);
}

}  // namespace
}  // namespace rad
