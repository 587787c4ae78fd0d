// A kind of surface added by this file alone and kernels/material.h: a perfect retroreflector,
// which sends light back the way it came, times its colour (RAD_SPECULAR_RETROREFLECTOR). No glTF
// material maps to it; the test adds it to the host's kinds (scene/surface_kinds.h) for
// materials named "retroreflector". Every pass draws it: the camera's three modes and the path
// tracer see what lies behind the camera in it, the progressive solve's shots carry the light
// back to where it left, and the direct light of a punctual light counts as kept there only what
// its colour does not send back. A mirror in its place fails each check.

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "solver/direct_light.h"
#include "device_fixture.h"
#include "scene/surface_kinds.h"
#include "render/path_tracer.h"
#include "render/renderer.h"
#include "render/view_pass.h"
#include "solved_scene.h"

namespace rad {
namespace {

using test::quad;
using test::sharedCompute;
using test::Solved;
using test::solveScene;
using test::TestScene;

constexpr float kColour = 0.8f;  // what the retroreflector sends back, per channel

void addRetroreflector() {
    static const bool added = [] {
        addSurfaceKind({"retroreflector", RAD_SPECULAR_RETROREFLECTOR,
                        [](const Material& m) { return m.name == "retroreflector"; },
                        [](const Material& m) { return glm::vec4(m.baseColor, 0.0f); }, false});
        return true;
    }();
    (void)added;
}

// A 2 x 2 m plane on z = 0 facing +z, a retroreflector of colour kColour (`mirror`: a mirror of
// that F0 instead), under a black lamp strip (Le = 1) on z = 1 facing down, x in [0, 0.5].
Scene planeUnderLamp(bool mirror, bool withLamp = true) {
    addRetroreflector();
    Scene scene;
    scene.path = "retroreflector test scene";
    Material plane;
    plane.name = mirror ? "mirror" : "retroreflector";
    plane.baseColor = glm::vec3(kColour);
    plane.reflectance = glm::vec3(kColour);
    plane.metallic = mirror ? 1.0f : 0.0f;
    plane.roughness = mirror ? 0.0f : 1.0f;
    Material lamp;
    lamp.name = "lamp";
    lamp.baseColor = lamp.reflectance = glm::vec3(0.0f);
    lamp.emission = glm::vec3(1.0f);
    scene.materials = {plane, lamp};
    scene.surfaces.push_back(quad("plane", {0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, 0));
    if (withLamp) scene.surfaces.push_back(quad("lamp", {0, 0, 1}, {0, 2, 1}, {0.5f, 2, 1}, {0.5f, 0, 1}, 1));
    return scene;
}

// Parallel rays from the plane z = 0.9 over x = 0.2, y = 1, tilted 0.3 toward +x on their way
// down: the retroreflector sends each back along itself into the lamp strip; a mirror sends it
// on to x of about 0.8, past the strip, into the dark.
View tiltedDown() {
    View v;
    v.orthographic = true;
    v.halfHeight = 0.05f;
    v.position = {0.2f, 1.0f, 0.9f};
    v.forward = glm::normalize(glm::vec3(0.3f, 0.0f, -1.0f));
    v.up = {0.0f, 1.0f, 0.0f};
    v.right = glm::cross(v.forward, v.up);
    return v;
}

// Each pixel's radiance against what it must be: the lamp's Le = 1 times kColour.
void expectLampTimesColour(const Image& image, double expected, const std::string& pass) {
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) ASSERT_NEAR(image.pixels[i][c], expected, 1e-5) << pass << ", pixel " << i;
}

TEST(AddedKind, EveryCameraPassSeesTheLampBehindTheCameraInARetroreflector) {
    // Every ray comes back along itself, after the plane, to the lamp (black, so nothing more):
    // each sample is Le kColour exactly, in the radiosity mode (the lamp's radiosity B / pi = 1 at
    // its vertices), the direct and final-gather modes, and the path tracer. Through a mirror,
    // the same rays miss the lamp: 0.
    for (const bool mirror : {false, true}) {
        const TestScene s(planeUnderLamp(mirror), 0.25);
        ProgressiveResult result;
        const Solved solved = solveScene(s, 100'000, &result);
        const View view = tiltedDown();
        const double expected = mirror ? 0.0 : kColour;
        const std::string kind = mirror ? "mirror: " : "retroreflector: ";
        const DeviceElements elements(sharedCompute(), s.elements);
        std::vector<glm::vec3> radiance = result.radiosity;  // B / pi: the lamp's 1, the plane's 0
        for (glm::vec3& b : radiance) b /= static_cast<float>(M_PI);
        expectLampTimesColour(renderView(s, elements, solved.vertices,
                                         vertexValues(s.elements, solved.vertices, radiance), view, {8, 8, 2}),
                              expected, kind + "radiosity");
        for (RenderMode mode : {RenderMode::direct, RenderMode::finalGather}) {
            ViewPassOptions o;
            o.width = o.height = 8;
            o.samples = 4;
            o.mode = mode;
            const PixelEstimate e =
                renderViewPass(s, s.elements, elements, solved.vertices, solved.elementIrradiance, view, o, solved.caustic);
            expectLampTimesColour(e.image, expected, kind + renderModeName(mode));
        }
        PathTraceOptions p;
        p.width = p.height = 8;
        p.samples = 4;
        expectLampTimesColour(pathTrace(s, view, p).image, expected, kind + "path tracer");
    }
}

TEST(AddedKind, TheShotsCarryTheLightBackToWhereItLeft) {
    // The lamp's rays that reach the plane leave 1 - kColour there and go back to the lamp with
    // the rest (kernels/specular_walk.h splits each ray's power exactly, in fixed point): the
    // black lamp receives kColour / (1 - kColour) = 4 times what the plane keeps, whatever the
    // view factor: to 1e-4, the single-precision sums of each element's power over the batches
    // (measured 2.7e-6). Off a mirror the light goes on past the strip, and the lamp receives a
    // small share of it.
    for (const bool mirror : {false, true}) {
        const TestScene s(planeUnderLamp(mirror), 0.25);
        ProgressiveResult r;
        solveScene(s, 1'000'000, &r);
        glm::dvec3 lamp(0.0), plane(0.0);
        for (std::size_t e = 0; e < r.incident.size(); ++e) {
            const std::uint32_t surface = s.mesh().patches[s.elements.elements()[e].patch].surface;
            (surface == s.surface("lamp") ? lamp : plane) += glm::dvec3(r.incident[e]);
        }
        for (int c = 0; c < 3; ++c) {
            ASSERT_GT(plane[c], 0.0);
            const double ratio = lamp[c] / plane[c];
            if (mirror) EXPECT_LT(ratio, 1.0) << c;
            else EXPECT_NEAR(ratio, kColour / (1.0 - kColour), 1e-4 * ratio) << c;
        }
    }
}

TEST(AddedKind, APointLightsDirectLightIsKeptAsTheColourSays) {
    // A point light of 1 W/sr 0.5 m over the plane's level and 1 m to the side of it, no lamp:
    // the plane keeps 1 - kColour of the light that reaches it at every angle (material_keeps;
    // the rest goes back to the light). Its irradiance integrated over the plane on a fine grid
    // in double; the direct light's midpoint rule on elements 1/8 m across differs from that by
    // about 1e-4. A mirror keeps 1 - F, Schlick's F growing toward the grazing angles the light
    // meets here: 18 % less.
    const glm::dvec3 at(-1.0, 1.0, 0.5);
    double reaching = 0.0;
    const int n = 2000;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const glm::dvec3 d = at - glm::dvec3(2.0 * (i + 0.5) / n, 2.0 * (j + 0.5) / n, 0.0);
            const double r2 = glm::dot(d, d);
            reaching += d.z / (r2 * std::sqrt(r2)) * (4.0 / n / n);
        }
    const double expected = (1.0 - kColour) * reaching;
    for (const bool mirror : {false, true}) {
        Scene scene = planeUnderLamp(mirror, false);
        Light light;
        light.position = at;
        light.intensity = glm::dvec3(1.0);
        scene.lights.push_back(light);
        const TestScene s(std::move(scene), 0.125);
        const DirectLight direct = directLight(s, s.elements, 1);
        glm::dvec3 kept(0.0);
        for (const glm::dvec3& arrived : direct.arrived) kept += arrived;
        for (int c = 0; c < 3; ++c) {
            if (mirror) EXPECT_LT(kept[c], 0.9 * expected) << c;
            else EXPECT_NEAR(kept[c], expected, 1e-3 * expected) << c;
        }
    }
}

}  // namespace
}  // namespace rad
