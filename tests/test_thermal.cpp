// Radiative heat exchange on the host: the net-radiation method against closed forms
// (thermal/net_radiation.h), exchange factors, and the properties file's refusals
// (thermal/thermal_properties.h). The device's part, on estimated view factors, is in
// test_exchange.cpp.

#include <cmath>
#include <fstream>

#include <gtest/gtest.h>

#include "thermal/net_radiation.h"
#include "thermal/thermal_properties.h"
#include "util/error.h"

namespace rad {
namespace {

double blackEmission(double t) {
    return kStefanBoltzmann * std::pow(t, 4);
}

SurfaceCondition atTemperature(double emissivity, double t) {
    SurfaceCondition c;
    c.emissivity = emissivity;
    c.temperature = t;
    return c;
}

SurfaceCondition withFlux(double emissivity, double q) {
    SurfaceCondition c;
    c.emissivity = emissivity;
    c.temperatureGiven = false;
    c.heatFlux = q;
    return c;
}

TEST(NetRadiation, TwoInfinitePlatesExchangeTheClosedForm) {
    // F12 = F21 = 1: q = sigma (T1^4 - T2^4) / (1/e1 + 1/e2 - 1).
    ExchangeProblem p;
    p.area = {1.0, 1.0};
    p.factor = {{0.0, 1.0}, {1.0, 0.0}};
    p.conditions = {atTemperature(0.3, 600.0), atTemperature(0.7, 300.0)};
    const ExchangeSolution s = solveNetRadiation(p);
    const double q = (blackEmission(600.0) - blackEmission(300.0)) / (1.0 / 0.3 + 1.0 / 0.7 - 1.0);
    EXPECT_NEAR(s.netHeat[0], q, 1e-12 * q);
    EXPECT_NEAR(s.netHeat[1], -q, 1e-12 * q);
    EXPECT_NEAR(s.toEnvironment, 0.0, 1e-12 * q);
    // Black plates: q = sigma (T1^4 - T2^4).
    p.conditions = {atTemperature(1.0, 600.0), atTemperature(1.0, 300.0)};
    EXPECT_NEAR(solveNetRadiation(p).netHeat[0], blackEmission(600.0) - blackEmission(300.0), 1e-9);
}

TEST(NetRadiation, AThreeSurfaceEnclosureWithAReradiatingWallMatchesItsNetwork) {
    // A long duct of equilateral cross-section: F_ij = 1/2 between its three walls (unit area per
    // unit length). Wall 3 is reradiating (q = 0): Oppenheim's network gives
    // Q1 = (Eb1 - Eb2) / (R1 + Rmid + R2), R = (1 - e) / (e A), Rmid = 1 / (A F12 + 1 / (1 / (A F13)
    // + 1 / (A F23))), and wall 3 at J3 = (J1 + J2) / 2 = sigma T3^4.
    ExchangeProblem p;
    p.area = {1.0, 1.0, 1.0};
    p.factor = {{0.0, 0.5, 0.5}, {0.5, 0.0, 0.5}, {0.5, 0.5, 0.0}};
    p.conditions = {atTemperature(0.5, 1000.0), atTemperature(0.8, 500.0), withFlux(0.3, 0.0)};
    const ExchangeSolution s = solveNetRadiation(p);
    const double r1 = (1.0 - 0.5) / 0.5, r2 = (1.0 - 0.8) / 0.8, mid = 1.0 / (0.5 + 1.0 / (2.0 + 2.0));
    const double q1 = (blackEmission(1000.0) - blackEmission(500.0)) / (r1 + mid + r2);
    EXPECT_NEAR(s.netHeat[0], q1, 1e-12 * q1);
    EXPECT_NEAR(s.netHeat[1], -q1, 1e-12 * q1);
    EXPECT_NEAR(s.netHeat[2], 0.0, 1e-12 * q1);
    const double j1 = blackEmission(1000.0) - q1 * r1, j2 = blackEmission(500.0) + q1 * r2;
    EXPECT_NEAR(s.temperature[2], std::pow(0.5 * (j1 + j2) / kStefanBoltzmann, 0.25), 1e-9);
    // The reradiating wall's emissivity does not matter.
    p.conditions[2].emissivity = 0.9;
    EXPECT_NEAR(solveNetRadiation(p).temperature[2], s.temperature[2], 1e-9);
}

TEST(NetRadiation, AnOpenSceneLosesToTheEnvironmentWhatItsSurfacesNetLose) {
    // Two facing plates that see each other by 0.2 and the environment by 0.8, at 400 K and 300 K,
    // under an environment at 250 K: the net heats sum to what the environment takes.
    ExchangeProblem p;
    p.area = {1.0, 1.0};
    p.factor = {{0.0, 0.2}, {0.2, 0.0}};
    p.conditions = {atTemperature(0.6, 400.0), atTemperature(0.9, 300.0)};
    p.environmentTemperature = 250.0;
    const ExchangeSolution s = solveNetRadiation(p);
    EXPECT_NEAR(s.netHeat[0] + s.netHeat[1], s.toEnvironment, 1e-12 * std::fabs(s.netHeat[0]));
    EXPECT_GT(s.toEnvironment, 0.0);
    // H_1 = 0.2 J_2 + 0.8 sigma T_env^4.
    EXPECT_NEAR(s.irradiance[0], 0.2 * s.radiosity[1] + 0.8 * blackEmission(250.0), 1e-9);
}

TEST(NetRadiation, ExchangeFactorsAreClosedAndReciprocal) {
    ExchangeProblem p;
    p.area = {1.0, 2.0, 3.0};
    // An enclosure's factors: reciprocal (A_i F_ij = A_j F_ji) and closed.
    p.factor = {{0.0, 0.5, 0.5}, {0.25, 0.25, 0.5}, {1.0 / 6.0, 1.0 / 3.0, 0.5}};
    p.conditions = {atTemperature(0.4, 300.0), atTemperature(0.7, 300.0), atTemperature(0.9, 300.0)};
    const auto g = exchangeFactors(p);
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_NEAR(g[i][0] + g[i][1] + g[i][2], 1.0, 1e-12);
        for (std::size_t j = 0; j < 3; ++j)
            EXPECT_NEAR(p.conditions[i].emissivity * p.area[i] * g[i][j],
                        p.conditions[j].emissivity * p.area[j] * g[j][i], 1e-12);
    }
    // Black surfaces absorb what they see first: G = F.
    for (SurfaceCondition& c : p.conditions) c.emissivity = 1.0;
    const auto black = exchangeFactors(p);
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j) EXPECT_NEAR(black[i][j], p.factor[i][j], 1e-12);
}

TEST(NetRadiation, OnlyImposedFluxesInAClosedSceneAreRefused) {
    ExchangeProblem p;
    p.area = {1.0, 1.0};
    p.factor = {{0.0, 1.0}, {1.0, 0.0}};
    p.conditions = {withFlux(0.5, 10.0), withFlux(0.5, -10.0)};
    EXPECT_THROW(solveNetRadiation(p), InputError);
    // As estimated factors leave it: closed to rounding, not exactly singular.
    p.factor = {{1e-14, 1.0 - 2e-14}, {1.0 - 1e-14, 3e-14}};
    EXPECT_THROW(solveNetRadiation(p), InputError);
    // One temperature anchors them.
    p.conditions[1] = atTemperature(0.5, 300.0);
    EXPECT_NO_THROW(solveNetRadiation(p));
}

// A properties file with `text`, read for surfaces a, b and c.
// A file of the running test's own: ctest runs the tests of this file side by side, as separate
// processes, and one shared name let one test read another's rows.
std::string propertiesPath() {
    return testing::TempDir() + testing::UnitTest::GetInstance()->current_test_info()->name() + "-properties.csv";
}

std::vector<SurfaceCondition> readText(const std::string& text, const ThermalDefaults& defaults = {}) {
    const std::string path = propertiesPath();
    std::ofstream(path) << text;
    return readThermalProperties(path, {"a", "b", "c"}, defaults);
}

TEST(ThermalProperties, ReadsTemperaturesFluxesAndDefaults) {
    const auto c = readText("surface,emissivity,temperature,heat_flux\na,0.5,300,\n\"b\", 1 ,,-20\n", {0.9, 250.0});
    EXPECT_TRUE(c[0].temperatureGiven);
    EXPECT_EQ(c[0].temperature, 300.0);
    EXPECT_EQ(c[0].emissivity, 0.5);
    EXPECT_FALSE(c[1].temperatureGiven);
    EXPECT_EQ(c[1].heatFlux, -20.0);
    EXPECT_EQ(c[2].emissivity, 0.9);  // not listed: the defaults
    EXPECT_EQ(c[2].temperature, 250.0);
}

TEST(ThermalProperties, RefusesBadRowsNamingTheFileAndTheLine) {
    const std::pair<const char*, const char*> cases[] = {
        {"surface,emissivity,temperature\na,0.5,300\nz,0.5,300\n", "line 3: the scene has no surface side named 'z'"},
        {"surface,emissivity,temperature\na,0,300\n", "line 2: the emissivity of 'a' is 0, outside (0, 1]"},
        {"surface,emissivity,temperature\na,1.5,300\n", "line 2: the emissivity of 'a' is 1.5, outside (0, 1]"},
        {"surface,emissivity,temperature\na,0.5,-1\n", "line 2: the temperature of 'a' is negative"},
        {"surface,temperature\na,300\n", "line 1: the header has no 'emissivity' column"},
        {"surface,emissivity\na,0.5\n", "line 1: the header has neither a 'temperature' nor a 'heat_flux' column"},
        {"surface,emissivity,temperature\na,0.5\n", "line 2: has 2 fields, fewer than the header's 3"},
        {"surface,emissivity,temperature\na,0.5,warm\n", "line 2: temperature 'warm' is not a finite number"},
        {"surface,emissivity,temperature,heat_flux\na,0.5,300,10\n", "line 2: surface 'a' has both"},
        {"surface,emissivity,temperature\na,0.5,300\na,0.5,300\n", "line 3: surface 'a' is listed twice"},
        {"surface,emissivity,colour\n", "line 1: unknown column 'colour'"},
    };
    for (const auto& [text, problem] : cases) {
        try {
            readText(text, {0.5, 300.0});
            ADD_FAILURE() << "accepted: " << text;
        } catch (const FileError& e) {
            EXPECT_EQ(e.path(), propertiesPath());
            EXPECT_NE(e.problem().find(problem), std::string::npos) << e.what();
        }
    }
    // A surface neither listed nor covered by both defaults.
    EXPECT_THROW(readText("surface,emissivity,temperature\na,0.5,300\n", {0.5, std::nullopt}), InputError);
}

}  // namespace
}  // namespace rad
