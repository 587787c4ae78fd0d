// The camera pass and the image files: emitters show their radiance, the EXR round-trips.

#include <cmath>
#include <filesystem>

#include <gtest/gtest.h>

#include "device_fixture.h"
#include "io/image_files.h"
#include "mesh/vertices.h"
#include "render/renderer.h"
#include "render/view.h"
#include "shared_math.h"
#include "solver/progressive_solver.h"

namespace rad {
namespace {

using test::TestScene;
using test::sharedCompute;

struct Lit {
    MeshVertices vertices;
    std::vector<glm::vec3> radiance;
};

Lit solveAndShade(const TestScene& s, std::uint64_t rays) {
    ProgressiveOptions options;
    options.rays = rays;
    const auto r = ProgressiveSolver(s, s.elements).solve(options);
    Lit lit{weldVertices(s.mesh(), s.elements), {}};
    lit.radiance = vertexValues(s.elements, lit.vertices, r.radiosity);
    for (glm::vec3& v : lit.radiance) v /= static_cast<float>(kPi);
    return lit;
}

TEST(Render, EmitterPixelsShowTheEmittedRadiance) {
    // Look up at the facing squares' lamp (Le = 1, reflectance 0): every pixel that sees its
    // front must read exactly 1.
    const TestScene s("scenes/facing-squares.gltf");
    const Lit lit = solveAndShade(s, 100'000);
    View view;
    view.position = glm::vec3(glm::dvec3(0.5, 0.5, 0.5) - s.scene().origin);  // positions are relative to the origin
    view.forward = {0, 1, 0};
    view.right = {1, 0, 0};
    view.up = {0, 0, -1};
    view.yfov = 1.0f;
    const Image image = renderView(s, DeviceElements(sharedCompute(), s.elements), lit.vertices, lit.radiance, view, {64, 48, 2});
    ASSERT_EQ(image.width, 64);
    ASSERT_EQ(image.height, 48);
    for (const glm::vec3& p : image.pixels)
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(p[c], 1.0f, 0.01f);
}

TEST(Render, MirrorsShowWhatTheyReflectAndWhatTheyEmit) {
    // The radiosity mode follows mirrors: a mirror of F0 = 0.9 seen at normal incidence shows
    // the lamp it faces (Le = 1) at exactly 0.9, plus its own emission (0.25 here), which the
    // sample adds where it meets the mirror (0.9 alone: a mirror that did not glow; 0.25 or a
    // diffuse grey: one that was not followed).
    Scene scene = loadGltf(test::sourcePath("tests/data/specular/mirror-facing-lamp.gltf"));
    for (Material& m : scene.materials)
        if (m.name == "mirror") m.emission = glm::vec3(0.25f);
    const TestScene s(std::move(scene), 0.25);
    const Lit lit = solveAndShade(s, 100'000);
    const Image image = renderView(s, DeviceElements(sharedCompute(), s.elements), lit.vertices, lit.radiance,
                                   test::alongZView(s.scene(), 0.5, -1.0f), {16, 16, 2});
    for (const glm::vec3& p : image.pixels)
        for (int c = 0; c < 3; ++c) ASSERT_NEAR(p[c], 0.9f + 0.25f, 1e-5f);
}

TEST(Render, CornellLightAndExrRoundTrip) {
    const TestScene s("scenes/cornell-box.gltf", 0.05);
    const Lit lit = solveAndShade(s, 1'000'000);
    const View view = chooseView(s.scene(), "");
    ASSERT_EQ(view.name, "cornell");
    const Image image = renderView(s, DeviceElements(sharedCompute(), s.elements), lit.vertices, lit.radiance, view, {96, 80, 2});
    const std::string path = (std::filesystem::temp_directory_path() / "radiosity-test-render.exr").string();
    writeExr(path, image);
    const Image back = readExr(path);
    std::filesystem::remove(path);
    ASSERT_EQ(back.width, 96);
    ASSERT_EQ(back.height, 80);
    EXPECT_TRUE(back.pixels == image.pixels);
    // The light's centre is straight up at x = 0.278 m, y = 0.5483 m, z = 0.2795 m. Project it.
    const glm::vec3 target = glm::vec3(glm::dvec3(0.278, 0.5483, 0.2795) - s.scene().origin);
    const glm::vec3 d = target - view.position;
    const float depth = glm::dot(d, view.forward), t = std::tan(0.5f * view.yfov);
    const float aspect = 96.0f / 80.0f;
    const int px = static_cast<int>((glm::dot(d, view.right) / depth / (t * aspect) + 1.0f) * 0.5f * 96.0f);
    const int py = static_cast<int>((1.0f - glm::dot(d, view.up) / depth / t) * 0.5f * 80.0f);
    const glm::vec3 light = back.at(px, py);
    // Emitted radiance (17, 12, 4) plus the little the light reflects (its base colour is 0.78).
    EXPECT_NEAR(light.x, 17.0f, 0.01f * 17.0f);
    EXPECT_NEAR(light.y, 12.0f, 0.01f * 12.0f);
    EXPECT_NEAR(light.z, 4.0f, 0.01f * 4.0f);
    EXPECT_GE(light.x, 17.0f);
    // Walls are far dimmer and never negative or NaN.
    for (const glm::vec3& p : back.pixels)
        for (int c = 0; c < 3; ++c) ASSERT_TRUE(std::isfinite(p[c]) && p[c] >= 0.0f);
}

}  // namespace
}  // namespace rad
