// Two levels (patches shoot, finer elements receive) and adaptive refinement on the device.

#include <cmath>

#include <gtest/gtest.h>

#include "device_fixture.h"
#include "util/analytic_form_factors.h"
#include "mesh/vertices.h"
#include "shared_math.h"
#include "solver/progressive_solver.h"
#include "solver/refinement.h"
#include "solver/surface_means.h"

namespace rad {
namespace {

using test::TestScene;
using test::sharedCompute;

ProgressiveResult solve(const TestScene& s, const ElementMesh& elements, const ProgressiveOptions& options) {
    return ProgressiveSolver(s, elements).solve(options);
}

glm::dvec3 centroid(const std::array<glm::vec3, 3>& p) {
    return (glm::dvec3(p[0]) + glm::dvec3(p[1]) + glm::dvec3(p[2])) / 3.0;
}

// The occluder scene (scenes/generate.py): the light's square (side 0.4 at height 2) over a
// square occluder (side 0.6 at height 0.8) casts an umbra out to 0.2 + 0.1 x 2 / 1.2 = 0.367 m
// from the floor's centre and a penumbra out to -0.2 + 0.5 x 2 / 1.2 = 0.633 m, in the
// larger of |x| and |z| (the scene is centred on the floor's centre in x and z).
constexpr double kUmbra = 0.2 + 0.1 * 2.0 / 1.2, kPenumbra = -0.2 + 0.5 * 2.0 / 1.2;

double squareRadius(const TestScene& s, const Element& e) {
    const glm::dvec3 c = centroid(e.p) + s.scene().origin;
    return std::max(std::fabs(c.x), std::fabs(c.z));
}

// Receivers finer than shooters are finer sources too: a patch's rays start from its elements
// in proportion to the power each holds. With elements of 1/8 m under patches of 1/2 m, the
// closed cube's face means come out as a uniform mesh of 1/8 m has them, where the coarse
// patches alone are off by up to 0.45 %. Reference: the independent path tracer of
// FloorLitClosedCube (standard errors under 1.5e-4); with 4 M rays the solver's own noise in a
// face mean is about 1e-4 (seeds 1 to 3).
TEST(TwoLevelLong, FineElementsMakeCoarsePatchesShootAsFinely) {
    const TestScene s("scenes/closed-cube.gltf", 0.5);
    ProgressiveOptions options;
    options.rays = 4'000'000;
    options.tolerance = 1e-4;
    auto worst = [&](const ElementMesh& elements) {
        const ProgressiveResult r = solve(s, elements, options);
        EXPECT_LT(r.energy.relativeResidual(), 1e-5);
        double largest = 0.0;
        const auto means = surfaceMeans(s.mesh(), elements, r.radiosity);
        for (std::size_t i = 0; i < means.size(); ++i) {
            const std::string& name = s.mesh().surfaces[i].name;
            const double expected = name == "floor" ? 1.104305 : (name == "ceiling" ? 0.171168 : 0.181213);
            largest = std::max(largest, std::fabs(means[i].x / kPi / expected - 1.0));
        }
        return largest;
    };
    const double coarse = worst(s.elements), fine = worst(ElementMesh::uniform(s.mesh(), 0.125));
    EXPECT_GT(coarse, 0.003);  // the coarse mesh's own error, for the comparison to mean something
    EXPECT_LT(fine, 0.0015);   // uniform 1/8 m patches: 0.0007
}

// Direct light only (the light's shots, nothing reflected yet): every element of the floor
// outside the penumbra has radiosity rho E, with E the irradiance from the light's square by
// the closed form at its centroid. The elements are 3 cm in 25 cm patches, so a ray landing
// in the wrong element would show far beyond the noise.
TEST(TwoLevelLong, DirectLightOnElementsMatchesTheClosedForm) {
    const TestScene s("tests/data/solve/occluder.gltf", 0.25);
    const ElementMesh fine = ElementMesh::uniform(s.mesh(), 0.03);
    const std::size_t floor = s.surface("floor"), light = s.surface("light");
    ProgressiveOptions options;
    options.rays = 8'000'000;
    options.maxShots = s.mesh().surfaces[light].patchCount;  // the light's patches, one batch
    const ProgressiveResult r = solve(s, fine, options);
    ASSERT_EQ(r.tallies.shots, options.maxShots);

    std::vector<glm::dvec3> square;  // the light, as the scene has it
    for (std::uint32_t p = 0; p < s.mesh().patches.size(); ++p)
        if (s.mesh().patches[p].surface == light)
            for (const glm::vec3& v : s.mesh().patches[p].p) square.push_back(glm::dvec3(v));
    glm::dvec3 lo = square[0], hi = square[0];
    for (const glm::dvec3& v : square) lo = glm::min(lo, v), hi = glm::max(hi, v);
    const std::vector<glm::dvec3> polygon{{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, lo.y, hi.z}, {lo.x, lo.y, hi.z}};
    const double exitance = kPi * 10.0, rho = 0.5;
    const double perRay = r.energy.emitted.x / static_cast<double>(options.rays);

    double sumZ2 = 0.0;
    std::size_t count = 0;
    for (std::uint32_t e = 0; e < fine.elements().size(); ++e) {
        const Element& element = fine.elements()[e];
        if (s.mesh().patches[element.patch].surface != floor || squareRadius(s, element) < kPenumbra + 0.03) continue;
        const double expected =
            rho * exitance * pointToPolygonFactor(centroid(element.p), glm::dvec3(0.0, 1.0, 0.0), polygon);
        // Each ray brings about perRay: the element's count of rays is Poisson at most
        // (stratification only lowers it), and its relative error 1 / sqrt(count).
        const double rays = expected / rho * element.area / perRay;
        const double z = (r.radiosity[e].x - expected) / (expected / std::sqrt(rays));
        ASSERT_LT(std::fabs(z), 6.0) << "element " << e << " at " << squareRadius(s, element);
        sumZ2 += z * z;
        ++count;
    }
    ASSERT_GT(count, 1000u);
    EXPECT_LT(sumZ2 / static_cast<double>(count), 1.5);  // about 1 for Poisson noise, under it when stratified
}

// Direct irradiance on the occluder scene's floor, exactly: the light's rectangle less the
// occluder's shadow on the light's plane seen from the point, a rectangle too (both squares are
// horizontal and axis-aligned).
struct OccluderScene {
    double floorY, lightY, occluderY;
    glm::dvec2 light0, light1, occluder0, occluder1;  // (x, z) corners
    double exitance;

    explicit OccluderScene(const TestScene& s) : exitance(kPi * 10.0) {
        auto bounds = [&](const std::string& name, double& y, glm::dvec2& lo, glm::dvec2& hi) {
            const std::size_t surface = s.surface(name);
            lo = glm::dvec2(1e30), hi = glm::dvec2(-1e30);
            for (const Patch& p : s.mesh().patches)
                if (p.surface == surface)
                    for (const glm::vec3& v : p.p) {
                        lo = glm::min(lo, glm::dvec2(v.x, v.z)), hi = glm::max(hi, glm::dvec2(v.x, v.z));
                        y = v.y;
                    }
        };
        glm::dvec2 f0, f1;
        bounds("floor", floorY, f0, f1);
        bounds("light", lightY, light0, light1);
        bounds("occluder", occluderY, occluder0, occluder1);
    }

    static std::vector<glm::dvec3> rectangle(glm::dvec2 lo, glm::dvec2 hi, double y) {
        return {{lo.x, y, lo.y}, {hi.x, y, lo.y}, {hi.x, y, hi.y}, {lo.x, y, hi.y}};
    }

    double irradiance(const glm::dvec3& p) const {
        const glm::dvec3 up(0.0, 1.0, 0.0);
        double factor = pointToPolygonFactor(p, up, rectangle(light0, light1, lightY));
        const double t = (lightY - p.y) / (occluderY - p.y);  // the occluder projected from p
        const glm::dvec2 base(p.x, p.z);
        const glm::dvec2 lo = glm::max(light0, base + (occluder0 - base) * t);
        const glm::dvec2 hi = glm::min(light1, base + (occluder1 - base) * t);
        if (lo.x < hi.x && lo.y < hi.y) factor -= pointToPolygonFactor(p, up, rectangle(lo, hi, lightY));
        return exitance * std::max(factor, 0.0);
    }
};

// How far shading by the elements' vertex values departs from the exact direct light over the
// floor, each element given its exact mean (what a solve estimates): the area-weighted mean
// absolute difference, over the mean.
double shadingError(const TestScene& s, const ElementMesh& elements, const OccluderScene& exact) {
    const std::size_t floor = s.surface("floor");
    const auto& list = elements.elements();
    // Points of a 6 x 6 grid in barycentric coordinates (weights (i + 1/3, j + 1/3) / 6 ...).
    std::vector<glm::dvec3> points;
    for (int i = 0; i < 6; ++i)
        for (int j = 0; i + j < 6; ++j) {
            for (const auto& [u, v] : {std::pair{(i + 1.0 / 3) / 6, (j + 1.0 / 3) / 6}, {(i + 2.0 / 3) / 6, (j + 2.0 / 3) / 6}})
                if (u + v < 1.0) points.push_back({u, v, 1.0 - u - v});
        }
    std::vector<glm::vec3> mean(list.size(), glm::vec3(0.0f));
    for (std::size_t e = 0; e < list.size(); ++e) {
        if (s.mesh().patches[list[e].patch].surface != floor) continue;
        double sum = 0.0;
        for (const glm::dvec3& w : points)
            sum += exact.irradiance(w.x * glm::dvec3(list[e].p[0]) + w.y * glm::dvec3(list[e].p[1]) + w.z * glm::dvec3(list[e].p[2]));
        mean[e] = glm::vec3(static_cast<float>(sum / points.size()));
    }
    const MeshVertices vertices = weldVertices(s.mesh(), elements);
    const std::vector<glm::vec3> atVertices = vertexValues(elements, vertices, mean);
    double error = 0.0, total = 0.0;
    for (std::size_t e = 0; e < list.size(); ++e) {
        if (s.mesh().patches[list[e].patch].surface != floor) continue;
        for (const glm::dvec3& w : points) {
            double shaded = 0.0;
            for (int k = 0; k < 3; ++k) shaded += w[k] * atVertices[vertices.corners[e][k]].x;
            const double truth =
                exact.irradiance(w.x * glm::dvec3(list[e].p[0]) + w.y * glm::dvec3(list[e].p[1]) + w.z * glm::dvec3(list[e].p[2]));
            error += list[e].area * std::fabs(shaded - truth);
            total += list[e].area * truth;
        }
    }
    return error / total;
}

std::size_t floorElements(const TestScene& s, const ElementMesh& elements) {
    return elementsPerSurface(s.mesh(), elements)[s.surface("floor")];
}

// Adaptive refinement splits where the shadow's edges cross the floor, leaves the lit floor
// and the umbra's middle as they were, and buys a much better shading of the direct light
// with far fewer elements than splitting every patch once.
TEST(Adaptive, RefinesTheShadowsEdgesOnly) {
    const TestScene s("tests/data/solve/occluder.gltf", 0.1);
    const OccluderScene exact(s);
    ElementMesh elements = ElementMesh::uniform(s.mesh(), 0.0);
    ProgressiveOptions provisional;
    provisional.rays = 2'000'000;
    provisional.tolerance = 1e-2;
    AdaptiveOptions options;
    options.minEdge = s.mesh().patchSize / 8.0;
    options.passes = 3;
    // A final solve with plenty of rays, so that noise does not hold the splitting back: this
    // test is about where the mesh is refined and what that buys.
    options.finalRays = 64'000'000;
    const auto passes = refineAdaptively(s, elements, provisional, options);
    ASSERT_FALSE(passes.empty());

    // A split element's centroid is within a patch's diagonal of the penumbra.
    const std::size_t floor = s.surface("floor");
    const double margin = 1.5 * s.mesh().patchSize;
    for (const Element& e : elements.elements()) {
        if (s.mesh().patches[e.patch].surface != floor || e.level == 0) continue;
        EXPECT_GT(squareRadius(s, e), kUmbra - margin);
        EXPECT_LT(squareRadius(s, e), kPenumbra + margin);
    }
    // Measured (threshold 0.05): the error falls from 0.0146 to 0.0077 with 2873 floor
    // elements; splitting every patch once takes 6728 (and gives 0.0039).
    const ElementMesh coarse = ElementMesh::uniform(s.mesh(), 0.0);
    const ElementMesh halved = ElementMesh::uniform(s.mesh(), 0.55 * s.mesh().patchSize);
    EXPECT_LT(shadingError(s, elements, exact), 0.65 * shadingError(s, coarse, exact));
    EXPECT_LT(floorElements(s, elements), 0.6 * floorElements(s, halved));

    // The final solve on the refined elements balances.
    ProgressiveOptions last;
    last.rays = 2'000'000;
    last.tolerance = 1e-3;
    EXPECT_LT(solve(s, elements, last).energy.relativeResidual(), 1e-5);
}

}  // namespace
}  // namespace rad
