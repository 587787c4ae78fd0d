// Emitters (light/emitter.h): the emissive surfaces' power, sampling and direct light against
// closed forms and against the device, and a light that is not a surface reaching both solve
// strategies through the interface alone.

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "device_fixture.h"
#include "util/analytic_form_factors.h"
#include "light/emitter.h"
#include "shared_math.h"
#include "solver/refinement.h"
#include "solver/solve_strategy.h"
#include "solver/surface_means.h"

namespace rad {
namespace {

using test::TestScene;

// The facing squares: the top (y = 1) emits Le = 1 downwards onto the bottom (y = 0), both
// [0, 1]^2 in x and z; the mesh's coordinates are relative to the scene's origin.
struct FacingSquares : TestScene {
    FacingSquares() : TestScene("scenes/facing-squares.gltf", 0.25) {}
    glm::dvec3 at(double x, double y, double z) const { return glm::dvec3(x, y, z) - scene().origin; }
};

TEST(Emitters, EmissiveSurfacesEmitPiLeTimesTheirArea) {
    const FacingSquares s;
    ASSERT_EQ(s.emitters().list().size(), 1u);
    const double area = s.mesh().surfaces[s.surface("top")].area;
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(s.emitters().power()[c], kPi * area, 1e-6 * kPi * area);
    // Their patches carry Le in the per-patch system; the others nothing.
    for (std::size_t p = 0; p < s.mesh().patches.size(); ++p) {
        const bool lamp = s.mesh().patches[p].surface == s.surface("top");
        EXPECT_EQ(s.patches().emission[p], glm::vec3(lamp ? 1.0f : 0.0f)) << p;
    }
}

TEST(Emitters, SampledRaysFindTheClosedFormFactor) {
    // Directions drawn from the lamp that cross the bottom square's plane inside it: their share
    // estimates F(top -> bottom), and their mean cosine is 2/3 (cosine-distributed).
    const FacingSquares s;
    const Emitter& lamp = *s.emitters().list().front();
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const int n = 200'000;
    int hits = 0;
    double cosines = 0.0;
    for (int k = 0; k < n; ++k) {
        const EmissionSample e = lamp.sample(glm::dvec4(u(rng), u(rng), u(rng), u(rng)));
        cosines += glm::dot(e.direction, e.normal);
        const glm::dvec3 corner = s.at(0, 0, 0);
        if (e.direction.y >= 0.0) continue;
        const glm::dvec3 p = e.position + e.direction * ((corner.y - e.position.y) / e.direction.y);
        hits += p.x >= corner.x && p.x <= corner.x + 1.0 && p.z >= corner.z && p.z <= corner.z + 1.0;
    }
    const double f = parallelSquaresFactor(1.0, 1.0);
    EXPECT_NEAR(static_cast<double>(hits) / n, f, 4.0 * std::sqrt(f * (1.0 - f) / n));
    EXPECT_NEAR(cosines / n, 2.0 / 3.0, 4.0 * std::sqrt(1.0 / 18.0 / n));  // Var(cos) = 1/2 - 4/9
}

TEST(Emitters, SamplesCarryThePowerOfEmittersOfEveryColour) {
    // Two lamps of different colours: the mean power a sample stands for is the emitted power.
    const TestScene s("tests/data/pathtrace/two-sided-lamp.gltf", 0.25);
    const Emitter& lamps = *s.emitters().list().front();
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const int n = 100'000;
    glm::dvec3 sum(0.0), squares(0.0);
    for (int k = 0; k < n; ++k) {
        const glm::dvec3 p = lamps.sample(glm::dvec4(u(rng), u(rng), u(rng), u(rng))).power;
        sum += p;
        squares += p * p;
    }
    for (int c = 0; c < 3; ++c) {
        const double mean = sum[c] / n, sigma = std::sqrt(std::max(0.0, squares[c] / n - mean * mean) / n);
        EXPECT_NEAR(mean, lamps.power()[c], 4.0 * sigma + 1e-9 * lamps.power()[c]) << c;
    }
}

TEST(Emitters, IrradianceIntegratesToThePowerThatArrives) {
    // Over the bottom square, the lamp's irradiance sums to its power times F(top -> bottom).
    const FacingSquares s;
    const Emitter& lamp = *s.emitters().list().front();
    const int n = 64;
    double arrived = 0.0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            arrived += lamp.irradiance(s.at((i + 0.5) / n, 0.0, (j + 0.5) / n), glm::dvec3(0, 1, 0)).x / (n * n);
    // The midpoint rule's error on this smooth field is about 1e-5 of the power at n = 64.
    EXPECT_NEAR(arrived, lamp.power().x * parallelSquaresFactor(1.0, 1.0), 1e-4 * lamp.power().x);
    // Behind the lamp, nothing.
    EXPECT_EQ(lamp.irradiance(s.at(0.5, 2.0, 0.5), glm::dvec3(0, -1, 0)), glm::dvec3(0.0));
}

TEST(Emitters, DeviceDirectLightAgreesWithTheHost) {
    // The refinement's direct light (kernels/refine.cl, from the emitters' direct sources) at
    // the seven points of each bottom element, unoccluded, against the host's irradiance there.
    const FacingSquares s;
    const Emitter& lamp = *s.emitters().list().front();
    const MeshSurface& bottom = s.mesh().surfaces[s.surface("bottom")];
    std::vector<std::uint32_t> which;
    for (std::uint32_t k = 0; k < bottom.patchCount; ++k) which.push_back(bottom.firstPatch + k);
    RefinementOptions allSources;
    allSources.visibilityShooters = 1000;  // every lamp patch, none left out and made up for
    const std::vector<DirectVariation> device = directVariation(s, s.elements, which, allSources);
    for (std::size_t k = 0; k < which.size(); ++k) {
        const Element& e = s.elements.elements()[which[k]];
        const glm::dvec3 a(e.p[0]), b(e.p[1]), c(e.p[2]), centre = (a + b + c) / 3.0;
        const glm::dvec3 sa = centre + 0.95 * (a - centre), sb = centre + 0.95 * (b - centre),
                         sc = centre + 0.95 * (c - centre);
        double mean = 0.0;
        for (const glm::dvec3& p : {sa, sb, sc, 0.5 * (sa + sb), 0.5 * (sb + sc), 0.5 * (sc + sa), centre})
            mean += lamp.irradiance(p, glm::dvec3(0, 1, 0)).x / 7.0;
        // Single precision on the device (and a polynomial arctangent good to 4e-8) against double.
        EXPECT_NEAR(device[k].mean, mean, 1e-4 * mean) << "element " << which[k];
    }
}

// A light that is not a surface, as point lights and the sky are: the irradiance H reaches every
// receiver directly, and the solvers shoot what they reflect.
class UniformIrradiance : public Emitter {
public:
    UniformIrradiance(double irradiance, double area) : h_(irradiance), area_(area) {}
    std::string describe() const override { return "a uniform irradiance"; }
    glm::dvec3 power() const override { return glm::dvec3(h_ * area_); }
    EmissionSample sample(const glm::dvec4&) const override { return {}; }
    glm::dvec3 irradiance(const glm::dvec3&, const glm::dvec3&) const override { return glm::dvec3(h_); }
    // Delivered by the solver's direct-light service as its irradiance at every element.
    DirectDelivery delivery() const override { return DirectDelivery::unoccluded; }

private:
    double h_, area_;
};

TEST(Emitters, LightThatIsNotShotReachesEveryStrategy) {
    // The white furnace (every face emits E = 1, rho = 0.5, closed) with H = 1 more on every
    // face: B = (E + rho H) / (1 - rho) = 3 everywhere, where the surfaces alone give 2.
    TestScene s("tests/data/solve/white-furnace.gltf", 0.25);
    double area = 0.0;
    for (const MeshSurface& surface : s.mesh().surfaces) area += surface.area;
    s.addEmitter(std::make_unique<UniformIrradiance>(1.0, area));
    // Tolerances, relative. Progressive: the solve shoots about 2e6 / (1 - rho) = 4e6 rays, a
    // face takes about a sixth, so the reflected two thirds of B carry at most 1 / sqrt(6.7e5)
    // = 1.2e-3 of noise (less: the samples are stratified); 0.005 is six of those standard
    // deviations (measured at seed 1: 2.4e-4). Matrix: the rows of a closed furnace sum to 1, so
    // B = 3 solves the discrete system exactly, up to the solvers' residual and float rounding.
    struct Case {
        const char* method;
        const char* solver;
        OptionValues values;
        double tolerance;
    };
    const Case cases[] = {{"shoot", "progressive", {{"--rays", 2e6}, {"--tolerance", 1e-4}}, 0.005},
                          {"hemicube", "direct", {{"--hemicube-res", 32}}, 1e-5},
                          {"shoot", "jacobi", {{"--rays-per-patch", 1024}, {"--residual", 1e-9}}, 1e-5}};
    for (const Case& c : cases) {
        const Solution solution = makeSolveStrategy({c.method, c.solver, c.values, 1})->solve(s, {});
        for (const glm::dvec3& mean : surfaceMeans(s.mesh(), solution.elements, solution.radiosity))
            for (int k = 0; k < 3; ++k) EXPECT_NEAR(mean[k], 3.0, c.tolerance * 3.0) << c.method << " " << c.solver;
        // Emitted: (E + H) A.
        EXPECT_NEAR(solution.energy.emitted.x, 2.0 * area, 1e-5 * area) << c.method << " " << c.solver;
        EXPECT_LT(solution.energy.relativeResidual(), 1e-3) << c.method << " " << c.solver;
    }
}

}  // namespace
}  // namespace rad
