// The environment map on the device: the kernels' mapping, filter and sampling against the
// host's (kernels/environment.h through kernels/probes.cl), its direct light on open surfaces
// against the integral of the filtered map, and what the camera pass and the path tracer see.

#include <cmath>
#include <random>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "solver/direct_light.h"
#include "device/kernel_arguments.h"
#include "device_fixture.h"
#include "light/emitter.h"
#include "device/device_environment.h"
#include "render/path_tracer.h"
#include "render/renderer.h"
#include "scene/environment_map.h"
#include "shared_math.h"

namespace rad {
namespace {

using test::sharedCompute;
using test::TestScene;

std::string mapPath(const std::string& name) {
    return test::sourcePath("tests/data/environment/" + name);
}

std::shared_ptr<const EnvironmentMap> loadMap(const std::string& name) {
    return std::make_shared<const EnvironmentMap>(loadEnvironmentMap(mapPath(name), 1.0));
}

TestScene sceneUnder(const std::string& scene, const std::string& map, double patchSize) {
    Scene loaded = loadGltf(mapPath(scene));
    loaded.environment = loadMap(map);
    return TestScene(std::move(loaded), patchSize);
}

// The irradiance on a plane of unit normal n from the filtered map, nothing in the way: the
// midpoint rule over `sub` x `sub` points per texel, in u and in cos(theta).
double filteredIrradiance(const EnvironmentMap& map, const glm::dvec3& n, int sub = 24) {
    double sum = 0.0;
    for (int y = 0; y < map.height; ++y) {
        const double top = std::cos(kPi * y / map.height), bottom = std::cos(kPi * (y + 1.0) / map.height);
        const double cell = 2.0 * kPi / map.width * (top - bottom) / (sub * sub);
        for (int x = 0; x < map.width; ++x)
            for (int i = 0; i < sub; ++i)
                for (int j = 0; j < sub; ++j) {
                    const double c = top + (j + 0.5) / sub * (bottom - top);
                    const glm::dvec3 d = environmentDirection((x + (i + 0.5) / sub) / map.width, std::acos(c) / kPi);
                    const double cosine = glm::dot(d, n);
                    if (cosine > 0.0) sum += environmentRadiance(map, d).x * cosine * cell;
                }
    }
    return sum;
}

// The mean irradiance over a surface's elements, and its standard error: on an open, flat
// surface every element's estimate is an independent draw of the same estimator (its own
// rays), so the spread between elements measures the estimator's variance.
struct SurfaceMean {
    double mean = 0.0, standardError = 0.0;
};
SurfaceMean meanIrradiance(const TestScene& s, const DirectLight& direct, const std::string& surface) {
    const std::size_t wanted = s.surface(surface);
    double sum = 0.0, squares = 0.0, n = 0.0;
    for (std::size_t e = 0; e < direct.arrived.size(); ++e) {
        const Element& element = s.elements.elements()[e];
        if (s.mesh().patches[element.patch].surface != wanted) continue;
        const double irradiance = direct.arrived[e].x / element.area;
        sum += irradiance;
        squares += irradiance * irradiance;
        n += 1.0;
    }
    SurfaceMean m;
    m.mean = sum / n;
    m.standardError = std::sqrt(std::max(0.0, squares / n - m.mean * m.mean) / (n - 1.0));
    return m;
}

TEST(EnvironmentMap, KernelsMapFilterAndSampleAsTheHostDoes) {
    const auto map = loadMap("sun.exr");
    Scene scene;
    scene.environment = map;
    const EnvironmentTables tables = buildEnvironmentTables(scene);
    const EnvironmentSampling sampling = environmentSampling(*map);
    std::mt19937 rng(11);
    std::normal_distribution<double> g;
    std::vector<rad_float4> directions;
    std::vector<glm::dvec3> exact;
    std::vector<rad_uint2> draws;
    for (const glm::dvec3 axis : {glm::dvec3(1, 0, 0), glm::dvec3(0, 0, 1), glm::dvec3(0, 0, -1), glm::dvec3(0, 1, 0),
                                  glm::dvec3(0, -1, 0), glm::dvec3(-1, 0, 0)})
        exact.push_back(axis);
    while (exact.size() < 4000) exact.push_back(glm::normalize(glm::dvec3(g(rng), g(rng), g(rng))));
    for (const glm::dvec3& d : exact) {
        const glm::vec3 f(d);
        directions.push_back(float4Of(f));
        draws.push_back(rad_uint2{{static_cast<rad_uint>(rng()), static_cast<rad_uint>(rng())}});
    }
    const std::size_t count = directions.size();
    ComputeContext& compute = sharedCompute();
    const auto texels = DeviceArray<rad_float4>::upload(compute, tables.texels, "map");
    const auto rows = DeviceArray<rad_uint>::upload(compute, tables.rows, "rows");
    const auto columns = DeviceArray<rad_uint>::upload(compute, tables.columns, "columns");
    const auto dirArray = DeviceArray<rad_float4>::upload(compute, directions, "directions");
    const auto drawArray = DeviceArray<rad_uint2>::upload(compute, draws, "draws");
    const auto mapped = DeviceArray<rad_float4>::allocate(compute, count, "mapped");
    const auto radiance = DeviceArray<rad_float4>::allocate(compute, count, "radiance");
    const auto drawn = DeviceArray<rad_float4>::allocate(compute, count, "drawn");
    ProbeEnvironmentArgs args;
    args.info = tables.info;
    args.texels = texels;
    args.rows = rows;
    args.columns = columns;
    args.directions = dirArray;
    args.draws = drawArray;
    args.mapped = mapped;
    args.radiance = radiance;
    args.drawn = drawn;
    args.count = static_cast<rad_uint>(count);
    makeKernel<ProbeEnvironmentArgs>(compute, "probes.cl", "probe_environment").launch(args, count);
    const std::vector<rad_float4> m = mapped.read();
    const std::vector<rad_float4> r = radiance.read();
    const std::vector<rad_float4> d = drawn.read();
    int sunDraws = 0;
    for (std::size_t i = 0; i < count; ++i) {
        // The direction the device was given (rounded to float), in double.
        const glm::dvec3 given = glm::normalize(glm::dvec3(glm::vec3(exact[i])));
        const glm::dvec2 ut = environmentCoordinates(given);
        const double du = std::fabs(m[i].s[0] - ut.x);
        EXPECT_LT(std::min(du, 1.0 - du), 2e-6) << i;
        EXPECT_NEAR(m[i].s[1], ut.y, 2e-6) << i;
        const glm::dvec3 l = environmentRadiance(*map, given);
        EXPECT_NEAR(r[i].s[0], l.x, 1e-4 * (l.x + 1.0)) << i;  // the filter's weights carry float rounding
        // Densities agree away from texel edges, where float and double may pick neighbours.
        const double ex = ut.x * map->width, ey = ut.y * map->height;
        const bool nearEdge = std::fabs(ex - std::round(ex)) < 1e-3 || std::fabs(ey - std::round(ey)) < 1e-3;
        if (!nearEdge) {
            const double pdf = environmentPdf(*map, sampling, given);
            EXPECT_NEAR(m[i].s[2], pdf, 1e-4 * pdf + 1e-9) << i;
        }
        // A drawn direction is a unit vector whose density is what the sampler said.
        const glm::dvec3 e(d[i].s[0], d[i].s[1], d[i].s[2]);
        EXPECT_NEAR(glm::length(e), 1.0, 1e-5);
        const glm::dvec2 et = environmentCoordinates(glm::normalize(e));
        const double fx = et.x * map->width, fy = et.y * map->height;
        if (std::fabs(fx - std::round(fx)) > 1e-3 && std::fabs(fy - std::round(fy)) > 1e-3) {
            const double pdf = environmentPdf(*map, sampling, glm::normalize(e));
            EXPECT_NEAR(d[i].s[3], pdf, 1e-4 * pdf) << i;
            if (static_cast<int>(fx) >= 47 && static_cast<int>(fx) <= 48 && static_cast<int>(fy) >= 8 &&
                static_cast<int>(fy) <= 9)
                ++sunDraws;
        }
    }
    // The sun's four texels: drawn with their share of the tables, binomially.
    double sunShare = 0.0;
    for (int y = 8; y <= 9; ++y)
        for (int x = 47; x <= 48; ++x)
            sunShare += environmentPdf(*map, sampling, environmentDirection((x + 0.5) / 64.0, (y + 0.5) / 32.0)) *
                        environmentTexelSolidAngle(*map, y);
    const double n = static_cast<double>(count), sigma = std::sqrt(n * sunShare * (1.0 - sunShare));
    EXPECT_NEAR(sunDraws, n * sunShare, 5.0 * sigma);
    // The sun brings nearly all the light, and the tables spread its weight over the 4 x 4
    // texels its filter reaches: its own four are drawn nearly a quarter of the time.
    EXPECT_GT(sunShare, 0.2);
}

TEST(EnvironmentMap, AUniformMapLightsAnOpenPlaneWithPiL) {
    const TestScene s = sceneUnder("plane.gltf", "uniform.exr", 0.25);
    const DirectLight direct = directLight(s, s.elements, 1);
    const SurfaceMean m = meanIrradiance(s, direct, "plane");
    EXPECT_NEAR(m.mean, kPi, 5.0 * m.standardError);
    EXPECT_LT(m.standardError, 0.01 * kPi);  // multiple importance sampling keeps a uniform map calm
    // The plane is single-sided: its back sees the lower half of the map and absorbs it, found
    // with a sixteenth of the front's rays, so about four times the front's standard error.
    double area = 0.0;
    for (const Element& e : s.elements.elements()) area += e.area;
    EXPECT_NEAR(direct.absorbedByBacks.x / area, kPi, 5.0 * 4.0 * m.standardError);
}

TEST(EnvironmentMap, TheSunLightsWhatFacesItAsTheFilteredMapsIntegralSays) {
    // The test map's sun is above +Z, 39 degrees up; its ground is black. The quad facing +Z sees
    // the sun; the one facing -Z sees only sky; the plane facing up sees the sun at an angle.
    const auto map = loadMap("sun.exr");
    const TestScene quads = sceneUnder("facing-quads.gltf", "sun.exr", 0.125);
    const DirectLight direct = directLight(quads, quads.elements, 1);
    const TestScene plane = sceneUnder("plane.gltf", "sun.exr", 0.25);
    const DirectLight planeDirect = directLight(plane, plane.elements, 1);
    const struct {
        const TestScene& scene;
        const DirectLight& direct;
        const char* surface;
        glm::dvec3 normal;
    } cases[] = {{quads, direct, "toward_plus_z", {0, 0, 1}},
                 {quads, direct, "toward_minus_z", {0, 0, -1}},
                 {plane, planeDirect, "plane", {0, 1, 0}}};
    for (const auto& c : cases) {
        const double exact = filteredIrradiance(*map, c.normal);
        const SurfaceMean m = meanIrradiance(c.scene, c.direct, c.surface);
        EXPECT_NEAR(m.mean, exact, 5.0 * m.standardError + 1e-5 * exact) << c.surface;
        EXPECT_LT(m.standardError, 0.02 * exact) << c.surface;
    }
    EXPECT_GT(filteredIrradiance(*map, {0, 0, 1}), 100.0 * filteredIrradiance(*map, {0, 0, -1}));
}

TEST(EnvironmentMap, TheCameraPassAndThePathTracerSeeItAndAgreeWithTheDirectLight) {
    const auto map = loadMap("sun.exr");
    const TestScene s = sceneUnder("plane.gltf", "sun.exr", 0.25);
    // Looking straight down at the plane: a pixel's radiance is rho E / pi, E the filtered map's
    // irradiance (direct light only: the plane sees nothing else).
    const double rho = s.scene().materials[0].reflectance.x;
    const double expected = rho * filteredIrradiance(*map, {0, 1, 0}) / kPi;
    PathTraceOptions o;
    o.width = 16;
    o.height = 16;
    o.samples = 16;
    o.maxBounces = 1;
    const PathTraceResult r = pathTrace(s, test::topDownView(s.scene(), glm::dvec3(0.0, 0.5, 0.0), 0.5f), o);
    double sum = 0.0, squares = 0.0;
    for (const glm::vec3& p : r.image.pixels) {
        sum += p.x;
        squares += static_cast<double>(p.x) * p.x;
    }
    const double n = static_cast<double>(r.image.pixels.size()), mean = sum / n;
    const double standardError = std::sqrt(std::max(0.0, squares / n - mean * mean) / (n - 1.0));
    EXPECT_NEAR(mean, expected, 5.0 * standardError + 1e-5 * expected);
    EXPECT_LT(standardError, 0.02 * expected);  // the map's sun is sampled, not waited for
    // Looking at the sun: every ray leaves the scene, and the camera pass and the path tracer show
    // the filtered map there.
    const glm::dvec3 sun = environmentDirection(0.75, 9.0 / 32.0);
    View v;
    v.orthographic = true;
    v.halfHeight = 0.01f;
    v.position = glm::vec3(0.0f, 5.0f, 0.0f);
    v.forward = glm::vec3(sun);
    v.right = glm::normalize(glm::cross(v.forward, glm::vec3(0, 1, 0)));
    v.up = glm::cross(v.right, v.forward);
    const double shown = environmentRadiance(*map, sun).x;
    const PathTraceResult traced = pathTrace(s, v, o);
    const Image rendered = renderView(s, DeviceElements(s.compute(), s.elements), {}, {}, v, {4, 4, 1});
    for (const Image* image : {&traced.image, &rendered})
        for (const glm::vec3& p : image->pixels) EXPECT_NEAR(p.x, shown, 1e-3 * shown);
}

}  // namespace
}  // namespace rad
