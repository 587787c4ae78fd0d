// The lightmap's texels (lightmap/texel_bake.h) and what fills them (lightmap/texel_fill.h):
// the light over a surface against a closed form and against the solution, seams where a flat
// floor is split into two charts and between a made atlas's charts of a tube, a wall that goes through a floor, and a box standing on one.
//
// Tolerances come from the texels' own variance (the spread of a texel's samples over their
// count), summed over the texels a figure adds up, and checked to 5 standard deviations.

#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "device_fixture.h"
#include "lightmap/lightmap_layout.h"
#include "lightmap/texel_bake.h"
#include "lightmap/texel_fill.h"
#include "lightmap/texel_footprints.h"
#include "shared_math.h"
#include "solved_scene.h"

namespace rad {
namespace {

using test::quad;
using test::sharedCompute;
using test::Solved;
using test::solveScene;
using test::TestScene;

double luminance(const glm::vec3& c) {
    return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
}

BakedLightmap bake(const TestScene& s, const Solved& solved, const LightmapLayout& layout, RenderMode mode,
                   std::uint32_t samples) {
    const DeviceElements deviceElements(sharedCompute(), s.elements);
    const ViewPathSolution paths{s.elements, deviceElements, solved.vertices, solved.elementIrradiance, solved.caustic};
    LightmapBakeOptions options;
    options.samples = samples;
    options.mode = mode;
    return bakeLightmap(s, paths, layout, options);
}

Scene greyScene() {
    Scene scene;
    scene.path = "test scene";
    Material grey;
    grey.name = "grey";
    grey.reflectance = glm::vec3(0.5f);
    grey.baseColor = glm::vec3(0.5f);
    scene.materials.push_back(grey);
    return scene;
}

// The light over the faces of mesh surfaces (front sides) `sides`, summed over the texels as
// E times the area of those faces in each texel (W, luminance), and the sum's variance.
struct Integral {
    double power = 0.0, variance = 0.0, area = 0.0;
};
Integral integrate(const TestScene& s, const LightmapLayout& layout, const BakedLightmap& baked,
                   const std::vector<std::size_t>& sceneSurfaces) {
    Integral out;
    for (std::uint32_t page = 0; page < layout.pages; ++page) {
        const TexelFootprints f = texelFootprints(layout, s.mesh(), page);
        for (std::size_t i = 0; i < f.texels.size(); ++i) {
            double share = 0.0, before = 0.0;
            for (std::uint32_t k = i == 0 ? 0 : f.ends[i - 1]; k < f.ends[i]; ++k) {
                const std::uint32_t surface = s.mesh().faces[f.pieces[k].face].sceneSurface;
                if (std::find(sceneSurfaces.begin(), sceneSurfaces.end(), surface) != sceneSurfaces.end())
                    share += f.pieces[k].end - before;
                before = f.pieces[k].end;
            }
            const double area = share * f.area[i];
            const std::size_t t = f.texels[i];
            out.power += luminance(baked.pages[page].irradiance[t]) * area;
            out.variance += baked.pages[page].variance[t] * area * area;
            out.area += area;
        }
    }
    return out;
}

// The texels' own noise: the root of their mean variance over the texels holding surface that
// `chosen` (a texel's index in the page) picks; 0 where it picks none.
template <class Pick>
double texelNoise(const LightmapPage& page, Pick chosen) {
    double sum = 0.0, count = 0.0;
    for (std::size_t t = 0; t < page.area.size(); ++t)
        if (page.area[t] > 0.0 && chosen(t)) {
            sum += page.variance[t];
            count += 1.0;
        }
    return count > 0.0 ? std::sqrt(sum / count) : 0.0;
}

// Each seam point's two bilinear lookups of the first page's irradiance agree to `tolerance`;
// returns how many of them are lit.
std::size_t expectSeamLookupsAgree(const BakedLightmap& baked, const std::vector<SeamPoint>& points,
                                   double tolerance) {
    std::size_t lit = 0;
    for (const SeamPoint& p : points) {
        const double a = luminance(bilinear(baked.pages[0].irradiance, baked.size, p.a));
        const double b = luminance(bilinear(baked.pages[0].irradiance, baked.size, p.b));
        lit += a > 0.0;
        EXPECT_LT(std::fabs(a - b), tolerance) << "at " << p.a.x << ", " << p.a.y;
    }
    return lit;
}

TEST(Lightmap, APointLightsPowerOnAFloorIsItsIntensityTimesTheSolidAngle) {
    // A 1 x 1 m floor with a point light of 1 W/sr 0.5 m over its centre, nothing else: the
    // texels' E times their area adds up to I times the solid angle the floor subtends,
    // 4 asin(x y / sqrt((x^2 + h^2)(y^2 + h^2))) = 4 asin(1/2) = 2 pi / 3 (x = y = h = 0.5), in
    // both modes. Every sample is a point of the floor: at 1 / 45.37 m the floor's edges cut
    // through texels, so a texel that sampled past them, or a point drawn twice, would show.
    // Then the same floor double-sided and wound the other way (its front facing down, away
    // from the light): the lightmap holds the side that received the light, its back.
    for (const bool flipped : {false, true}) {
        Scene scene = greyScene();
        Surface floor =
            quad("floor", {-0.5f, -0.5f, 0.0f}, {0.5f, -0.5f, 0.0f}, {0.5f, 0.5f, 0.0f}, {-0.5f, 0.5f, 0.0f});
        if (flipped) {
            for (auto& t : floor.triangles) std::swap(t[1], t[2]);
            scene.materials[0].doubleSided = true;
        }
        scene.surfaces.push_back(floor);
        Light light;
        light.name = "bulb";
        light.type = Light::Type::Point;
        light.position = glm::dvec3(0.0, 0.0, 0.5);
        light.intensity = glm::dvec3(1.0);
        scene.lights.push_back(light);
        const TestScene s(std::move(scene), 0.1);
        const Solved solved = solveScene(s, 100'000);
        LightmapOptions options;
        options.texelSize = 1.0 / 45.37;
        options.pageSize = 64;
        const LightmapLayout layout = layoutLightmap(s.scene(), s.mesh(), options);
        const double expected = 2.0 * kPi / 3.0;
        for (RenderMode mode : {RenderMode::direct, RenderMode::finalGather}) {
            const BakedLightmap baked = bake(s, solved, layout, mode, 16);
            EXPECT_EQ(baked.backSides, flipped ? 2u : 0u);
            const Integral lit = integrate(s, layout, baked, {0});
            EXPECT_NEAR(lit.area, 1.0, 1e-9);
            EXPECT_NEAR(lit.power, expected, 5.0 * std::sqrt(lit.variance) + 1e-5 * expected)
                << renderModeName(mode) << (flipped ? ", flipped" : "");
        }
    }
}

TEST(Lightmap, TheFurnacesTexelsAddUpToTheSolutionOnEveryWall) {
    // The closed cube with every face emitting E = 1 and rho = 0.5: H = 2 everywhere. Per wall,
    // the texels' E over the wall's area equals the solution's mean H on it and 2, to 5 standard
    // deviations of the texels' sum plus 0.5 % for the solution's own error (its walls' means
    // with 4e6 rays are within 0.06 % of 2, the camera pass's furnace test says). Half the light
    // is direct (light samples of the other walls) and half the solution's, read as each mode
    // reads it: a light counted twice, or missed, moves every wall by a quarter. At 1 / 15.37 m
    // the walls' edges, where each meets three others, cut through texels, and every texel that
    // holds surface must keep samples: an anchor on a wall's edge that rounding put behind the
    // neighbouring wall would lose them all (not seen here even without the guards against it,
    // texel_footprints.cpp and lightmap.cl, but checked).
    const TestScene s("tests/data/solve/white-furnace.gltf", 0.1);
    ProgressiveResult solution;
    const Solved solved = solveScene(s, 4'000'000, &solution);
    LightmapOptions options;
    options.texelSize = 1.0 / 15.37;
    options.pageSize = 128;
    const LightmapLayout layout = layoutLightmap(s.scene(), s.mesh(), options);
    for (RenderMode mode : {RenderMode::direct, RenderMode::finalGather}) {
        const BakedLightmap baked = bake(s, solved, layout, mode, 8);
        for (std::uint32_t page = 0; page < layout.pages; ++page) {
            const TexelFootprints f = texelFootprints(layout, s.mesh(), page);
            for (std::size_t i = 0; i < f.texels.size(); ++i)
                EXPECT_GT(baked.pages[page].area[f.texels[i]], 0.0) << "texel " << f.texels[i] << " kept no sample";
        }
        for (std::size_t wall = 0; wall < s.scene().surfaces.size(); ++wall) {
            const Integral lit = integrate(s, layout, baked, {wall});
            double power = 0.0, area = 0.0;  // the solution's, over the wall's front elements
            const MeshSurface& side = s.mesh().surfaces[s.surface(s.scene().surfaces[wall].name)];
            for (std::uint32_t p = side.firstPatch; p < side.firstPatch + side.patchCount; ++p)
                for (std::uint32_t e = s.elements.elementStart()[p]; e < s.elements.elementStart()[p + 1]; ++e) {
                    power += luminance(solution.incident[e]);
                    area += s.elements.elements()[e].area;
                }
            const double mean = lit.power / lit.area, sigma = std::sqrt(lit.variance) / lit.area;
            EXPECT_NEAR(lit.area, area, 1e-4 * area);
            EXPECT_NEAR(mean, 2.0, 5.0 * sigma + 0.005 * 2.0) << renderModeName(mode) << " wall " << wall;
            EXPECT_NEAR(mean, power / area, 5.0 * sigma + 0.005 * 2.0) << renderModeName(mode) << " wall " << wall;
        }
    }
}

TEST(Lightmap, AFloorSplitIntoTwoChartsShowsNoSeam) {
    // A 2 x 1 m floor of two 1 x 1 m quads that meet along x = 0, laid by the scene's own
    // TEXCOORD_1 into two charts 8 texels apart, under a point light 1 m over the seam. Each
    // texel is baked on its own, so across the seam the two charts' bilinear lookups differ by
    // their noise; after stitching they agree to a tenth of it, while no texel that holds surface
    // moves by more than 5 of its standard deviations. Without stitching the first check fails.
    Scene scene = greyScene();
    Surface floor = quad("left", {-1.0f, -0.5f, 0.0f}, {0.0f, -0.5f, 0.0f}, {0.0f, 0.5f, 0.0f}, {-1.0f, 0.5f, 0.0f});
    const Surface right =
        quad("right", {0.0f, -0.5f, 0.0f}, {1.0f, -0.5f, 0.0f}, {1.0f, 0.5f, 0.0f}, {0.0f, 0.5f, 0.0f});
    floor.name = "floor";
    floor.positions.insert(floor.positions.end(), right.positions.begin(), right.positions.end());
    floor.triangles.push_back({4, 5, 6});
    floor.triangles.push_back({4, 6, 7});
    floor.triangleMaterial = {0, 0, 0, 0};
    // Left quad over u in [4, 28] / 64, the right one over [36, 60] / 64; v in [4, 28] / 64,
    // row 0 at y = 0.5 (v grows as y falls).
    auto uv = [](float u0, float x, float y) {
        return glm::vec2((u0 + 24.0f * x) / 64.0f, (4.0f + 24.0f * (0.5f - y)) / 64.0f);
    };
    floor.texCoords[1] = {uv(4, 0, -0.5f),  uv(4, 1, -0.5f),  uv(4, 1, 0.5f),  uv(4, 0, 0.5f),
                          uv(36, 0, -0.5f), uv(36, 1, -0.5f), uv(36, 1, 0.5f), uv(36, 0, 0.5f)};
    scene.surfaces.push_back(floor);
    Light light;
    light.name = "bulb";
    light.position = glm::dvec3(0.0, 0.0, 1.0);
    light.intensity = glm::dvec3(1.0);
    scene.lights.push_back(light);
    const TestScene s(std::move(scene), 0.1);
    const Solved solved = solveScene(s, 100'000);
    LightmapOptions options;
    options.pageSize = 64;
    const LightmapLayout layout = layoutLightmap(s.scene(), s.mesh(), options);
    ASSERT_TRUE(layout.fromScene) << layout.note;
    ASSERT_EQ(layout.charts, 2u);
    BakedLightmap baked = bake(s, solved, layout, RenderMode::finalGather, 8);
    fillGutters(baked, 2);
    const BakedLightmap unstitched = baked;
    const SeamReport seams = stitchSeams(baked, layout, s.mesh());
    EXPECT_EQ(seams.edges, 1u);
    const std::vector<SeamPoint> points = seamPoints(layout, s.mesh());
    ASSERT_EQ(points.size(), seams.samples);
    // The lookups' noise: the texels' own standard deviation near the seam (their mean square).
    const LightmapPage& page = unstitched.pages[0];
    const double noise = texelNoise(page, [](std::size_t t) { return t % 64 == 27 || t % 64 == 36; });
    ASSERT_GT(noise, 0.0);
    expectSeamLookupsAgree(baked, points, 0.1 * noise);
    for (std::size_t t = 0; t < page.area.size(); ++t)
        if (page.area[t] > 0.0)
            EXPECT_LE(std::fabs(luminance(baked.pages[0].irradiance[t]) - luminance(page.irradiance[t])),
                      5.0 * std::sqrt(page.variance[t]) + 1e-6)
                << "texel " << t;
    EXPECT_LT(seams.mismatchAfter, 0.1 * seams.mismatchBefore);
}

TEST(Lightmap, AMadeAtlasShowsNoSeamAcrossATubesCharts) {
    // An open tube (radius 0.5 m, 1 m long, 48 facets, wound outwards) under a point light 2 m
    // from its axis: the made atlas unrolls it into a few charts (no chart closes on itself), so
    // the smooth surface has seams along its length, some across the lit side. Before stitching
    // the two sides' bilinear lookups differ by their noise and by the step in the light between
    // the facets either side (their RMS 4 times the texels' noise here); after it, every seam
    // point's two lookups agree to within the texels' noise, so the seam is lost in it, and the
    // RMS falls by 10 times or more. Without stitching the first check fails.
    Scene scene = greyScene();
    Surface tube;
    tube.name = "tube";
    const int facets = 48, rings = 4;
    const double pi = 3.14159265358979323846;
    for (int j = 0; j <= rings; ++j)
        for (int i = 0; i < facets; ++i)
            tube.positions.push_back(glm::vec3(0.5f * static_cast<float>(std::cos(2.0 * pi * i / facets)),
                                               0.5f * static_cast<float>(std::sin(2.0 * pi * i / facets)),
                                               static_cast<float>(j) / rings));
    for (int j = 0; j < rings; ++j)
        for (int i = 0; i < facets; ++i) {
            const std::uint32_t a = j * facets + i, b = j * facets + (i + 1) % facets;
            tube.triangles.push_back({a, b, b + facets});
            tube.triangles.push_back({a, b + facets, a + facets});
            tube.triangleMaterial.push_back(0);
            tube.triangleMaterial.push_back(0);
        }
    scene.surfaces.push_back(tube);
    Light light;
    light.name = "bulb";
    light.position = glm::dvec3(2.0, 0.3, 0.5);
    light.intensity = glm::dvec3(4.0);
    scene.lights.push_back(light);
    const TestScene s(std::move(scene), 0.1);
    const Solved solved = solveScene(s, 100'000);
    LightmapOptions options;
    options.pageSize = 128;
    const LightmapLayout layout = layoutLightmap(s.scene(), s.mesh(), options);
    ASSERT_FALSE(layout.fromScene);
    ASSERT_GE(layout.charts, 2u);
    BakedLightmap baked = bake(s, solved, layout, RenderMode::finalGather, 8);
    fillGutters(baked, 2);
    const BakedLightmap unstitched = baked;
    const SeamReport seams = stitchSeams(baked, layout, s.mesh());
    EXPECT_GE(seams.edges, static_cast<std::uint64_t>(rings) * layout.charts);  // each cut runs the tube's length
    const std::vector<SeamPoint> points = seamPoints(layout, s.mesh());
    ASSERT_EQ(points.size(), seams.samples);
    // The lookups' noise: the texels' own standard deviation (their mean square) over the lit side.
    const LightmapPage& page = unstitched.pages[0];
    const double noise = texelNoise(page, [&](std::size_t t) { return page.variance[t] > 0.0; });
    ASSERT_GT(noise, 0.0);
    EXPECT_GT(expectSeamLookupsAgree(baked, points, noise), 0u);  // some seam crosses the lit side
    // Stitching evens out the sides, including the facets' own steps in the light (7.5 degrees
    // apart), without adding or losing light: the power over the tube holds to 5 standard
    // deviations of its sum.
    const Integral before = integrate(s, layout, unstitched, {0}), after = integrate(s, layout, baked, {0});
    EXPECT_NEAR(after.power, before.power, 5.0 * std::sqrt(before.variance));
    EXPECT_LT(seams.mismatchAfter, 0.1 * seams.mismatchBefore);
}

TEST(Lightmap, NoTexelAveragesLightAcrossAWallThatGoesThroughAFloor) {
    // A single-sided 1 x 1 m wall standing through a 4 x 4 m floor (half above, half below),
    // lit from +x and above by a directional light (travelling along (-0.6, 0.1, -0.8)): the
    // wall's front and the floor at x > 0 are lit, the floor behind the wall (x in (-0.375, 0)
    // near y = 0) lies in its shadow, and nothing reaches the wall below the floor (the floor
    // shadows it and its underside is black). The texels (1 / 23.3 m: their squares straddle
    // both the wall's foot and the floor's line) stand for the side of their anchor, so in final
    // gather every wall texel anchored below the floor and every floor texel anchored in the
    // shadow is exactly black, and every floor texel anchored on the lit side is fully lit.
    // Averaging over the whole footprint instead (the anchor's check removed) fails 19 of these
    // checks, in both directions. Direct mode reads the indirect light interpolated over
    // the solution's elements (0.1 m here), which carries it up to an element across the wall's
    // foot: there the black is checked from one element away.
    Scene scene = greyScene();
    scene.surfaces.push_back(
        quad("floor", {-2.0f, -2.0f, 0.0f}, {2.0f, -2.0f, 0.0f}, {2.0f, 2.0f, 0.0f}, {-2.0f, 2.0f, 0.0f}));
    scene.surfaces.push_back(
        quad("wall", {0.0f, -0.5f, -0.5f}, {0.0f, 0.5f, -0.5f}, {0.0f, 0.5f, 0.5f}, {0.0f, -0.5f, 0.5f}));
    Light sun;
    sun.name = "sun";
    sun.type = Light::Type::Directional;
    sun.direction = glm::normalize(glm::dvec3(-0.6, 0.1, -0.8));
    sun.intensity = glm::dvec3(1.0);
    scene.lights.push_back(sun);
    const TestScene s(std::move(scene), 0.1);
    const Solved solved = solveScene(s, 200'000);
    LightmapOptions options;
    options.texelSize = 1.0 / 23.3;
    options.pageSize = 128;
    const LightmapLayout layout = layoutLightmap(s.scene(), s.mesh(), options);
    for (RenderMode mode : {RenderMode::direct, RenderMode::finalGather}) {
        const BakedLightmap baked = bake(s, solved, layout, mode, 8);
        const double margin = mode == RenderMode::direct ? s.mesh().patchSize : 0.0;
        int wallBelow = 0, shadow = 0, lit = 0;
        for (std::uint32_t pageIndex = 0; pageIndex < layout.pages; ++pageIndex) {
            const TexelFootprints f = texelFootprints(layout, s.mesh(), pageIndex);
            for (std::size_t i = 0; i < f.texels.size(); ++i) {
                const TexelAnchor& anchor = f.anchors[i];
                const Face& face = s.mesh().faces[anchor.face];
                const glm::vec3 at =
                    face.p[0] + anchor.b1 * (face.p[1] - face.p[0]) + anchor.b2 * (face.p[2] - face.p[0]);
                const double e = luminance(baked.pages[pageIndex].irradiance[f.texels[i]]);
                const std::string where = renderModeName(mode) + " texel " + std::to_string(f.texels[i]) + " at (" +
                                          std::to_string(at.x) + ", " + std::to_string(at.y) + ", " +
                                          std::to_string(at.z) + ")";
                if (face.sceneSurface == 1 && at.z < -1e-6 - margin) {
                    ++wallBelow;
                    EXPECT_EQ(e, 0.0) << where;
                } else if (face.sceneSurface == 0 && at.x < -margin && at.x > -0.3 && std::fabs(at.y) < 0.4) {
                    ++shadow;
                    EXPECT_EQ(e, 0.0) << where;
                } else if (face.sceneSurface == 0 && at.x > 1e-6 && at.x < 0.3 && std::fabs(at.y) < 0.4) {
                    ++lit;
                    EXPECT_GT(e, 0.7) << where;  // the sun's 0.8 W/m^2, and the wall's light
                }
            }
        }
        EXPECT_GT(wallBelow, 50) << renderModeName(mode);
        EXPECT_GT(shadow, 50) << renderModeName(mode);
        EXPECT_GT(lit, 100) << renderModeName(mode);
    }
}

TEST(Lightmap, AFloorUnderABoxLendsNoDarkToTheFloorBesideIt) {
    // A 0.6 m box of single-sided faces (outwards, no bottom) standing on a 4 x 4 m floor under a
    // sun straight above: the floor beside the box is lit as the floor farther off is (the box's
    // sides face the sun edgewise, and the grey box reflects a little onto the floor at its
    // foot). The texels under the box hold the dark inside it, and a bilinear lookup on the lit
    // floor within half a texel of the box's foot reads one of them. Their anchors see only the
    // box's black backs, so they take their value from their neighbours: every lookup a quarter
    // texel from the foot reads at least 0.95 of the lit floor's light (without the anchors'
    // probes, 38 of the 76 fail, the lowest at 0.35).
    Scene scene = greyScene();
    scene.surfaces.push_back(
        quad("floor", {-2.0f, -2.0f, 0.0f}, {2.0f, -2.0f, 0.0f}, {2.0f, 2.0f, 0.0f}, {-2.0f, 2.0f, 0.0f}));
    const float h = 0.3f;
    auto box = [&](const std::string& name, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d) {
        scene.surfaces.push_back(quad(name, a, b, c, d));
    };
    box("top", {-h, -h, 2 * h}, {h, -h, 2 * h}, {h, h, 2 * h}, {-h, h, 2 * h});
    box("+x", {h, -h, 0}, {h, h, 0}, {h, h, 2 * h}, {h, -h, 2 * h});
    box("-x", {-h, h, 0}, {-h, -h, 0}, {-h, -h, 2 * h}, {-h, h, 2 * h});
    box("+y", {h, h, 0}, {-h, h, 0}, {-h, h, 2 * h}, {h, h, 2 * h});
    box("-y", {-h, -h, 0}, {h, -h, 0}, {h, -h, 2 * h}, {-h, -h, 2 * h});
    Light sun;
    sun.name = "sun";
    sun.type = Light::Type::Directional;
    sun.direction = glm::dvec3(0.0, 0.0, -1.0);
    sun.intensity = glm::dvec3(1.0);
    scene.lights.push_back(sun);
    const TestScene s(std::move(scene), 0.1);
    const Solved solved = solveScene(s, 200'000);
    LightmapOptions options;
    options.texelSize = 1.0 / 23.3;  // texels straddle the box's foot
    options.pageSize = 256;
    const LightmapLayout layout = layoutLightmap(s.scene(), s.mesh(), options);
    // 32 samples, two launches: the second reads what the first's probes found.
    BakedLightmap baked = bake(s, solved, layout, RenderMode::finalGather, 32);
    fillGutters(baked, LightmapOptions{}.gutter);
    // Where a floor point lies in the lightmap: its face's texel coordinates by barycentrics.
    auto lookup = [&](glm::vec3 q) {
        for (std::size_t f = 0; f < s.mesh().faces.size(); ++f) {
            const Face& face = s.mesh().faces[f];
            if (face.sceneSurface != 0) continue;
            const glm::vec3 e1 = face.p[1] - face.p[0], e2 = face.p[2] - face.p[0], d = q - face.p[0];
            const float det = e1.x * e2.y - e1.y * e2.x;
            const float b1 = (d.x * e2.y - d.y * e2.x) / det, b2 = (e1.x * d.y - e1.y * d.x) / det;
            if (b1 < 0 || b2 < 0 || b1 + b2 > 1) continue;
            const auto& t = layout.texels[f];
            const glm::dvec2 at = t[0] + double(b1) * (t[1] - t[0]) + double(b2) * (t[2] - t[0]);
            return luminance(bilinear(baked.pages[layout.pageOf[f]].irradiance, baked.size, at));
        }
        return -1.0;
    };
    double far = 0.0;
    for (int k = 0; k < 40; ++k) far += lookup({-1.5f + 0.075f * k, 1.5f, 0.0f}) / 40.0;
    ASSERT_GT(far, 0.9);  // the sun's 1 W/m^2 and a little reflected light
    const float out = h + 0.25f * float(options.texelSize);  // a quarter texel beside the foot
    int checked = 0;
    for (int k = 1; k < 20; ++k) {
        const float along = -h + 2 * h * k / 20.0f;
        for (const glm::vec3 q : {glm::vec3(out, along, 0), glm::vec3(-out, along, 0), glm::vec3(along, out, 0),
                                  glm::vec3(along, -out, 0)}) {
            EXPECT_GT(lookup(q), 0.95 * far) << "at (" << q.x << ", " << q.y << ")";
            ++checked;
        }
    }
    EXPECT_EQ(checked, 76);
}

}  // namespace
}  // namespace rad
