// Radiative heat exchange on estimated view factors (thermal/radiative_exchange.h): the
// closed form of concentric spheres, and a closed cube against the net-radiation solution on
// its closed-form view factors, each within the error bars the batches give.

#include <cmath>
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "device_fixture.h"
#include "util/analytic_form_factors.h"
#include "thermal/radiative_exchange.h"

namespace rad {
namespace {

using test::TestScene;

SurfaceCondition atTemperature(double emissivity, double t) {
    SurfaceCondition c;
    c.emissivity = emissivity;
    c.temperature = t;
    return c;
}

// The conditions for the mesh's surfaces, by name.
std::vector<SurfaceCondition> conditionsFor(const TestScene& s, const std::map<std::string, SurfaceCondition>& byName) {
    std::vector<SurfaceCondition> out;
    for (const MeshSurface& surface : s.mesh().surfaces) out.push_back(byName.at(surface.name));
    return out;
}

TEST(Exchange, ConcentricSpheresExchangeTheClosedForm) {
    // A convex body in an enclosure sees only the enclosure (F12 = 1, exactly, whatever the
    // tessellation), so Q = sigma A1 (T1^4 - T2^4) / (1/e1 + (A1/A2)(1/e2 - 1)) holds with the
    // tessellated areas; the estimate may differ by its own noise (and the correction's rounding).
    const TestScene s("tests/data/thermal/concentric-spheres.gltf");
    const auto conditions =
        conditionsFor(s, {{"inner", atTemperature(0.8, 400.0)}, {"outer", atTemperature(0.5, 300.0)}});
    ExchangeOptions o;
    o.raysPerSurface = 80'000;
    const ExchangeEstimate e = estimateExchange(s, conditions, o);
    const std::size_t inner = s.surface("inner"), outer = s.surface("outer");
    const double a1 = e.table.areas[inner], a2 = e.table.areas[outer];
    const double q =
        kStefanBoltzmann * a1 * (std::pow(400.0, 4) - std::pow(300.0, 4)) / (1.0 / 0.8 + (a1 / a2) * (1.0 / 0.5 - 1.0));
    EXPECT_NEAR(e.solution.netHeat[inner], q, 5.0 * e.netHeatStandardError[inner] + 1e-9 * q);
    EXPECT_NEAR(e.solution.netHeat[outer], -q, 5.0 * e.netHeatStandardError[outer] + 1e-9 * q);
}

TEST(Exchange, AClosedCubeMatchesTheSolutionOnItsClosedFormFactorsWithinItsErrorBars) {
    const TestScene s("scenes/closed-cube.gltf");
    const std::map<std::string, SurfaceCondition> byName = {
        {"floor", atTemperature(0.9, 550.0)}, {"ceiling", atTemperature(0.3, 300.0)},
        {"left", atTemperature(0.6, 400.0)},  {"right", atTemperature(0.8, 350.0)},
        {"front", atTemperature(0.5, 450.0)}, {"back", atTemperature(1.0, 320.0)}};
    const std::map<std::string, std::string> opposite = {{"floor", "ceiling"}, {"ceiling", "floor"}, {"left", "right"},
                                                         {"right", "left"},    {"front", "back"},    {"back", "front"}};
    const auto conditions = conditionsFor(s, byName);
    ExchangeOptions o;
    o.raysPerSurface = 160'000;
    const ExchangeEstimate e = estimateExchange(s, conditions, o);

    // The same problem on the closed-form factors of the unit cube.
    ExchangeProblem exact = e.problem;
    const std::size_t n = exact.area.size();
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j)
            exact.factor[i][j] = i == j                                              ? 0.0
                                 : opposite.at(e.table.names[i]) == e.table.names[j] ? parallelSquaresFactor(1.0, 1.0)
                                                                                     : perpendicularSquaresFactor();
    const ExchangeSolution truth = solveNetRadiation(exact);
    double sum = 0.0, largest = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        EXPECT_GT(e.netHeatStandardError[i], 0.0);
        EXPECT_NEAR(e.solution.netHeat[i], truth.netHeat[i], 5.0 * e.netHeatStandardError[i]) << e.table.names[i];
        sum += e.solution.netHeat[i];
        largest = std::max(largest, std::fabs(e.solution.netHeat[i]));
    }
    // Closed, and corrected for reciprocity and closure: the net heats sum to zero to rounding.
    EXPECT_NEAR(sum, 0.0, 1e-9 * largest);

    // The ceiling reradiating (no net flux): its temperature is solved for, with its own error bar.
    std::map<std::string, SurfaceCondition> reradiating = byName;
    reradiating["ceiling"].temperatureGiven = false;
    reradiating["ceiling"].heatFlux = 0.0;
    const ExchangeEstimate r = estimateExchange(s, conditionsFor(s, reradiating), o);
    ExchangeProblem rExact = exact;
    rExact.conditions = r.problem.conditions;
    const ExchangeSolution rTruth = solveNetRadiation(rExact);
    const std::size_t ceiling = s.surface("ceiling");
    EXPECT_LT(r.netHeatStandardError[ceiling], 1e-9 * largest);  // imposed: rounding only
    EXPECT_GT(r.temperatureStandardError[ceiling], 0.0);
    EXPECT_NEAR(r.solution.temperature[ceiling], rTruth.temperature[ceiling],
                5.0 * r.temperatureStandardError[ceiling]);
    EXPECT_NEAR(r.solution.netHeat[ceiling], 0.0, 1e-9 * largest);
}

TEST(Exchange, TwoFacingPlatesLoseToTheEnvironmentWhatTheClosedFormsSay) {
    // Unit squares 1 m apart: each sees the other by F = 0.1998 and the environment (at 250 K)
    // by the rest, black and grey. The truth is the net-radiation solution on the closed-form
    // factor; in an open scene the net heats add up to what the environment takes.
    const TestScene s("scenes/facing-squares.gltf");
    for (const double emissivity : {1.0, 0.4}) {
        const auto conditions =
            conditionsFor(s, {{"bottom", atTemperature(emissivity, 500.0)}, {"top", atTemperature(0.7, 350.0)}});
        ExchangeOptions o;
        o.raysPerSurface = 80'000;
        o.environmentTemperature = 250.0;
        const ExchangeEstimate e = estimateExchange(s, conditions, o);
        ExchangeProblem exact = e.problem;
        const double f = parallelSquaresFactor(1.0, 1.0);
        exact.factor = {{0.0, f}, {f, 0.0}};
        const ExchangeSolution truth = solveNetRadiation(exact);
        for (std::size_t i = 0; i < 2; ++i)
            EXPECT_NEAR(e.solution.netHeat[i], truth.netHeat[i], 5.0 * e.netHeatStandardError[i])
                << e.table.names[i] << " at emissivity " << emissivity;
        EXPECT_NEAR(e.solution.netHeat[0] + e.solution.netHeat[1], e.solution.toEnvironment,
                    1e-9 * std::fabs(e.solution.netHeat[0]));
        EXPECT_GT(e.solution.toEnvironment, 0.0);
        // Each plate's view that reaches no surface: 1 - F, within its error bars from the
        // batches, which measure the stratified estimator's spread and so lie below the
        // binomial bound sqrt(p (1 - p) / N) (and above 0: the batches differ).
        const double binomial = std::sqrt((1.0 - f) * f / static_cast<double>(e.raysPerSurface));
        for (std::size_t i = 0; i < 2; ++i) {
            EXPECT_NEAR(e.toSpace[i], 1.0 - f, 5.0 * e.toSpaceStandardError[i]) << e.table.names[i];
            EXPECT_GT(e.toSpaceStandardError[i], 0.0) << e.table.names[i];
            EXPECT_LT(e.toSpaceStandardError[i], binomial) << e.table.names[i];
        }
    }
}

TEST(Exchange, ConcentricSpheresLoseNothingToSpace) {
    const TestScene s("tests/data/thermal/concentric-spheres.gltf");
    const auto conditions =
        conditionsFor(s, {{"inner", atTemperature(0.8, 400.0)}, {"outer", atTemperature(0.5, 300.0)}});
    ExchangeOptions o;
    o.raysPerSurface = 8'000;
    const ExchangeEstimate e = estimateExchange(s, conditions, o);
    ASSERT_EQ(e.toSpace.size(), 2u);
    for (std::size_t i = 0; i < 2; ++i) {
        EXPECT_EQ(e.toSpace[i], 0.0) << e.table.names[i];
        EXPECT_EQ(e.toSpaceStandardError[i], 0.0) << e.table.names[i];
    }
}

}  // namespace
}  // namespace rad
