// The radiosity pass's specular transport (kernels/shoot.cl's walk through them, specular_walk.h): shots that meet
// mirrors and glass go on through them, and the diffuse surfaces receive the light they send.
// References: a mirror's image by the contour-integral form factor, a thin pane's transmission by
// quadrature over the Fresnel reflectance, and a furnace that lossless mirrors and glass must
// leave undisturbed. Tolerances: five standard deviations of a binomial count of the rays that
// land (an upper bound for stratified rays).

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "solver/direct_light.h"
#include "device_fixture.h"
#include "util/analytic_form_factors.h"
#include "solver/punctual_caustics.h"
#include "light/punctual_lights.h"
#include "optics_reference.h"
#include "solver/progressive_solver.h"
#include "solver/surface_means.h"

namespace rad {
namespace {

using test::TestScene;

// Power arriving on each surface, W per channel, summed over its elements.
std::vector<glm::dvec3> surfacePower(const TestScene& s, const ProgressiveResult& r) {
    std::vector<glm::dvec3> sum(s.mesh().surfaces.size(), glm::dvec3(0.0));
    for (std::size_t e = 0; e < s.elements.elements().size(); ++e)
        sum[s.mesh().patches[s.elements.elements()[e].patch].surface] += glm::dvec3(r.incident[e]);
    return sum;
}

// Five standard deviations of the power `expected` (of `total` shot) when each of `rays` rays
// lands with probability expected / total.
double fiveSigma(double expected, double total, double rays) {
    const double p = expected / total;
    return 5.0 * total * std::sqrt(p * (1.0 - p) / rays);
}

// Gauss-Legendre nodes and weights on [0, 1]: the roots of the Legendre polynomial P_n by
// Newton's method from Chebyshev's estimates.
void gaussLegendre(int n, std::vector<double>& nodes, std::vector<double>& weights) {
    nodes.resize(n);
    weights.resize(n);
    for (int i = 0; i < n; ++i) {
        double x = std::cos(M_PI * (i + 0.75) / (n + 0.5)), derivative = 1.0;
        for (int iteration = 0; iteration < 100; ++iteration) {
            double p0 = 1.0, p1 = x;  // P_0, P_1, then up to P_n
            for (int k = 2; k <= n; ++k) {
                const double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
                p0 = p1;
                p1 = p2;
            }
            derivative = n * (x * p1 - p0) / (x * x - 1.0);
            const double step = p1 / derivative;
            x -= step;
            if (std::fabs(step) < 1e-15) break;
        }
        nodes[i] = 0.5 + 0.5 * x;
        weights[i] = 1.0 / ((1.0 - x * x) * derivative * derivative);  // (2 / ...) x 1/2 for [0, 1]
    }
}

// Gauss-Legendre quadrature (40 x 40) of f(x, z) over the square [-half, half]^2.
template <class F>
double overSquare(double half, F f) {
    static const auto rule = [] {
        std::pair<std::vector<double>, std::vector<double>> r;
        gaussLegendre(40, r.first, r.second);
        return r;
    }();
    const std::vector<double>&nodes = rule.first, &weights = rule.second;
    double sum = 0.0;
    for (std::size_t i = 0; i < nodes.size(); ++i)
        for (std::size_t k = 0; k < nodes.size(); ++k)
            sum += weights[i] * weights[k] * f(half * (2.0 * nodes[i] - 1.0), half * (2.0 * nodes[k] - 1.0));
    return 4.0 * half * half * sum;
}

// F between facing unit squares `gap` apart, each pair of points weighed by transmittance(cos):
// the quadrature over both squares.
template <class Transmittance>
double facingSquaresFactor(double gap, Transmittance transmittance) {
    return overSquare(0.5, [&](double x1, double y1) {
        return overSquare(0.5, [&](double x2, double y2) {
            const double dx = x1 - x2, dy = y1 - y2;
            const double r2 = dx * dx + dy * dy + gap * gap, cosine = gap / std::sqrt(r2);
            return cosine * cosine / (M_PI * r2) * transmittance(cosine);
        });
    });
}

TEST(SpecularTransport, AMirrorShowsTheLampToAReceiverBesideIt) {
    // A lamp (exitance 1, 1 m^2) and a black receiver side by side under a lossless mirror: the
    // receiver sees the lamp only in the mirror, so it receives the lamp's power times the form
    // factor from the lamp to the receiver's image in the mirror. The mirror absorbs nothing.
    const TestScene s("tests/data/specular/mirror-over-lamp.gltf", 0.25);
    ProgressiveOptions options;
    options.rays = 2'000'000;
    const ProgressiveResult r = ProgressiveSolver(s, s.elements).solve(options);
    EXPECT_LT(r.energy.relativeResidual(), 1e-6);
    const std::vector<glm::dvec3> lamp = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    const std::vector<glm::dvec3> image = {{1.5, 0, 1}, {2.5, 0, 1}, {2.5, 1, 1}, {1.5, 1, 1}};
    const double expected = polygonToPolygonFactor(lamp, image);  // x 1 W
    const std::vector<glm::dvec3> power = surfacePower(s, r);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(power[s.surface("receiver")][c], expected, fiveSigma(expected, 1.0, options.rays)) << c;
        EXPECT_EQ(power[s.surface("mirror")][c], 0.0) << c;  // F0 = 1 passes every ray's power on whole
    }
}

TEST(SpecularTransportLong, AThinPaneTransmitsByFresnelAtEveryAngle) {
    // Facing unit squares 0.25 m apart (lamp: exitance 1; receiver black) with a thin pane
    // between them (IOR 1.5, tint 0.9): each ray crosses it at its own angle and passes with
    // probability 1 - R(angle), tinted. The pane keeps (absorbs) the tint's tenth of what it passes.
    const TestScene s("tests/data/specular/pane-between-squares.gltf", 0.25);
    ProgressiveOptions options;
    options.rays = 8'000'000;
    const ProgressiveResult r = ProgressiveSolver(s, s.elements).solve(options);
    EXPECT_LT(r.energy.relativeResidual(), 1e-6);
    // The quadrature against the closed form first: it is exact to far below the noise.
    ASSERT_NEAR(facingSquaresFactor(0.25, [](double) { return 1.0; }), parallelSquaresFactor(1.0, 0.25), 1e-6);
    const double expected =
        0.9 * facingSquaresFactor(0.25, [](double cosine) { return 1.0 - test::dielectricFresnel(cosine, 1.0 / 1.5); });
    const double atNormalIncidence = 0.9 * 0.96 * parallelSquaresFactor(1.0, 0.25);
    const double tolerance = fiveSigma(expected, 1.0, options.rays);
    ASSERT_GT(std::fabs(expected - atNormalIncidence), 2.0 * tolerance);  // the test can tell them apart
    const std::vector<glm::dvec3> power = surfacePower(s, r);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(power[s.surface("receiver")][c], expected, tolerance) << c;
}

TEST(SpecularTransportLong, LosslessMirrorsAndGlassLeaveTheFurnaceUniform) {
    // The white furnace (B = 2 on every wall) with a lossless mirror sphere and a clear glass
    // sphere inside: they redirect light but absorb none, so the walls stay at 2; neither sphere
    // reflects diffusely (its radiosity is its emission, 0). A sphere that kept or doubled the
    // power it passes on would move the walls' mean by its share of the light.
    const TestScene s("tests/data/specular/furnace-with-spheres.gltf", 0.1);
    ProgressiveOptions options;
    options.tolerance = 1e-4;
    options.rays = 2'000'000;
    const ProgressiveResult r = ProgressiveSolver(s, s.elements).solve(options);
    EXPECT_EQ(r.stopped, StopReason::Tolerance);
    EXPECT_LT(r.energy.relativeResidual(), 1e-5);
    const std::vector<glm::dvec3> means = surfaceMeans(s.mesh(), s.elements, r.radiosity);
    const std::vector<glm::dvec3> power = surfacePower(s, r);
    for (const char* wall : {"floor", "ceiling", "left", "right", "front", "back"})
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(means[s.surface(wall)][c], 2.0, 0.005 * 2.0) << wall;
    for (const char* sphere : {"mirror_sphere", "glass_sphere"})
        for (int c = 0; c < 3; ++c) {
            EXPECT_EQ(means[s.surface(sphere)][c], 0.0) << sphere;
            // what a sphere keeps: only rays past the bounce limit (kernels/specular_walk.h)
            EXPECT_LT(power[s.surface(sphere)][c], 1e-4 * r.energy.emitted[c]) << sphere;
        }
}

// However the rays add into the delivered-power counters (formfactor/counter_layout.h), the
// sums are the same integers with rays that turn at mirrors and glass and leave power there.
// W per channel summed over each surface's elements, of a per-element list (empty: zeros).
std::vector<glm::dvec3> perSurface(const TestScene& s, const std::vector<glm::dvec3>& perElement) {
    std::vector<glm::dvec3> sum(s.mesh().surfaces.size(), glm::dvec3(0.0));
    for (std::size_t e = 0; e < perElement.size(); ++e)
        sum[s.mesh().patches[s.elements.elements()[e].patch].surface] += perElement[e];
    return sum;
}

TEST(SpecularTransport, APointLightsImageInAMirrorLightsTheReceiver) {
    // A point light (1 W/sr) 1 m over a lossless mirror, a 2 x 2 m receiver 1 m above the light,
    // facing down: it sees the light directly (found by shadow rays, 4 arcsin(1/2) W) and
    // the light's image 3 m below it, which no shadow ray can find: rays drawn from the light
    // (solver/punctual_caustics.h) bring it, 4 arcsin(1/10) W (the square's solid angle from the
    // image), within five binomial standard deviations of the rays' count (measured 0.3976
    // against 0.4007, one sigma 0.0022). The mirror keeps nothing. Without the light's rays the
    // receiver received only the direct 2.0944 W.
    const TestScene s("tests/data/specular/point-over-mirror.gltf", 0.25);
    const DirectLight direct = directLight(s, s.elements, 1);
    const std::vector<glm::dvec3> arrived = perSurface(s, direct.arrived);
    const std::vector<glm::dvec3> bySpecular = perSurface(s, direct.arrivedBySpecular);
    const double image = 4.0 * std::asin(0.1), straight = 4.0 * std::asin(0.5);
    const double tolerance = fiveSigma(image, 4.0 * M_PI, static_cast<double>(kPunctualCausticRays));
    const std::size_t receiver = s.surface("receiver"), mirror = s.surface("mirror");
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(bySpecular[receiver][c], image, tolerance) << c;
        // The direct part: the midpoint rule's error on elements 1/4 m across, 1 m off (5e-4).
        EXPECT_NEAR(arrived[receiver][c] - bySpecular[receiver][c], straight, 5e-4 * straight) << c;
        EXPECT_EQ(arrived[mirror][c], 0.0) << c;
    }
}

TEST(SpecularTransport, AMirrorKeepsWhatItAbsorbsAndPassesOnTheRest) {
    // The mirror scene with a lossy mirror (F0 = 0.5, Schlick's F at each angle). Following it
    // (the progressive solve), the mirror's elements count only what it keeps, 1 - F, exactly
    // (shadow rays and the midpoint rule: 2e-4 bounds the rule's error on elements 1/4 m across
    // at 1 m, measured 1.7e-5 against 40-point Gauss-Legendre quadrature), and the receiver gets F of the light's image
    // by the light's rays (five binomial sigma); the ledger still adds up to the light's power. As the matrix solvers
    // model it (a diffuse mirror), the direct light stops at the mirror: its elements count all that reaches them, and
    // nothing comes by way of it (else a mirror that reflects diffusely would also pass the light on: the energy
    // twice).
    Scene scene = loadGltf(test::sourcePath("tests/data/specular/point-over-mirror.gltf"));
    for (Material& m : scene.materials)
        if (m.name == "mirror") m.baseColor = m.reflectance = glm::vec3(0.5f);
    const TestScene s(std::move(scene), 0.25);
    auto schlick = [](double c) { return 0.5 + 0.5 * std::pow(1.0 - c, 5.0); };
    const std::size_t receiver = s.surface("receiver"), mirror = s.surface("mirror");
    const double reaching = overSquare(2.0, [](double x, double z) { return std::pow(x * x + z * z + 1.0, -1.5); });
    const double kept = overSquare(2.0, [&](double x, double z) {
        const double r = std::sqrt(x * x + z * z + 1.0);
        return (1.0 - schlick(1.0 / r)) / (r * r * r);
    });
    const double image = overSquare(1.0, [&](double x, double z) {
        const double r = std::sqrt(x * x + z * z + 9.0);
        return 3.0 * schlick(3.0 / r) / (r * r * r);
    });
    const glm::dvec3 power = s.emitters().power();

    const DirectLight follow = directLight(s, s.elements, 1);
    const std::vector<glm::dvec3> arrived = perSurface(s, follow.arrived);
    const std::vector<glm::dvec3> bySpecular = perSurface(s, follow.arrivedBySpecular);
    const double tolerance = fiveSigma(image, 4.0 * M_PI, static_cast<double>(kPunctualCausticRays));
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(arrived[mirror][c], kept, 2e-4 * kept) << c;
        EXPECT_NEAR(bySpecular[receiver][c], image, tolerance) << c;
        EXPECT_NEAR(follow.total()[c], power[c], 1e-9 * power[c]) << c;
    }

    const DirectLight diffuse = directLight(s, s.elements, 1, SpecularModel::diffuse);
    EXPECT_TRUE(diffuse.arrivedBySpecular.empty());
    const std::vector<glm::dvec3> whole = perSurface(s, diffuse.arrived);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(whole[mirror][c], reaching, 2e-4 * reaching) << c;
        EXPECT_NEAR(whole[receiver][c], arrived[receiver][c] - bySpecular[receiver][c], 1e-9) << c;
        EXPECT_NEAR(diffuse.total()[c], power[c], 1e-9 * power[c]) << c;
    }
}

TEST(SpecularTransport, APointLightsReflectionInAPaneIsFresnelsAndItsTransmissionDirect) {
    // The same with a thin pane (IOR 1.5, tint 0.9) for the mirror, and a black square 0.5 m
    // below it: the receiver gets the light's image weighed by the Fresnel reflectance at each
    // angle (quadrature: the integral of 3 / r^3 R(3 / r) over the receiver), by the light's
    // rays (measured 0.016071 against 0.016071 with seed 1, 0.01536 to 0.01606 with seeds 2 to 6,
    // one sigma 0.00044); the square below gets the
    // light through the pane by shadow rays alone, so nothing of it comes by way of glass (a ray
    // that crosses the pane straight on ends there).
    const TestScene s("tests/data/specular/point-over-pane.gltf", 0.25);
    const DirectLight direct = directLight(s, s.elements, 1);
    const std::vector<glm::dvec3> arrived = perSurface(s, direct.arrived);
    const std::vector<glm::dvec3> bySpecular = perSurface(s, direct.arrivedBySpecular);
    const double image = overSquare(1.0, [](double x, double z) {
        const double r = std::sqrt(x * x + z * z + 9.0);
        return 3.0 / (r * r * r) * test::dielectricFresnel(3.0 / r, 1.0 / 1.5);
    });
    const double tolerance = fiveSigma(image, 4.0 * M_PI, static_cast<double>(kPunctualCausticRays));
    // The square below, 1.5 m under the light, by shadow rays through the pane: (1 - R) x 0.9 at
    // each angle (the midpoint rule's error on elements 1/4 m across at 1.5 m: 6e-5 measured).
    const double through = overSquare(1.0, [](double x, double z) {
        const double r = std::sqrt(x * x + z * z + 2.25);
        return 0.9 * 1.5 / (r * r * r) * (1.0 - test::dielectricFresnel(1.5 / r, 1.0 / 1.5));
    });
    const std::size_t receiver = s.surface("receiver"), below = s.surface("below");
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(bySpecular[receiver][c], image, tolerance) << c;
        EXPECT_EQ(bySpecular[below][c], 0.0) << c;
        EXPECT_NEAR(arrived[below][c], through, 2e-4 * through) << c;
    }
}

TEST(SpecularTransport, ARoughMetalSendsAPointLightsLobeOnAndKeepsTheRest) {
    // A point light (1 W/sr) 1 m over a rough metal floor (roughness 0.5, F0 (0.9, 0.7, 0.4)) and a
    // 2 x 2 m receiver 1 m above the light, facing down. The rays from the light
    // (solver/punctual_caustics.h) that meet the metal go on in directions drawn from its GGX lobe
    // (material.h: glossy_scatter), and the receiver gets, by way of the metal,
    //   the integral over the floor x and the receiver y of f(wo, wi) cos_i / r^2 cos_o cos_y / d^2
    // (tests/optics_reference.h, Gauss-Legendre 40 x 40 on each square, the same to 1e-9 at 120 x
    // 60; f with the energy scale toward where the light goes, ggxEnergy), per channel, within five binomial
    // standard deviations of the rays' count (red: 0.3724 against 0.3767, one sigma 0.0020; a ray
    // passes on at most what it carries, so where the scale would pass on more the excess is
    // lost, a loss inside that bound). The
    // metal's elements count what it keeps: E (1 - albedo) at each point (the albedo by
    // quadrature of another sampling of the lobe, each direction's light scaled toward it), within five standard deviations of the
    // kernel's estimates of the albedo (one estimate's spread is below 0.15:
    // tests/test_kernels.cpp) over the 16 points of each element (red: 0.40598 against 0.40700;
    // the bound, 0.0057, is far above the error measured, so only a bias of a few % would show).
    const TestScene s("tests/data/specular/point-over-rough-metal.gltf", 0.25);
    const DirectLight direct = directLight(s, s.elements, 1);
    const std::vector<glm::dvec3> arrived = perSurface(s, direct.arrived);
    const std::vector<glm::dvec3> bySpecular = perSurface(s, direct.arrivedBySpecular);
    const std::size_t receiver = s.surface("receiver"), metal = s.surface("metal");
    const double alpha = 0.25;
    const glm::dvec3 f0(0.9, 0.7, 0.4), up(0.0, 1.0, 0.0);
    double largest = 0.0;  // the metal's largest element
    for (const Element& e : s.elements.elements())
        if (s.mesh().patches[e.patch].surface == metal) largest = std::max(largest, static_cast<double>(e.area));
    const double irradianceSquared =
        overSquare(2.0, [](double x, double z) { return std::pow(x * x + z * z + 1.0, -3.0); });
    const double keptSigma =
        0.15 *
        std::sqrt(largest / (kPunctualPointsPerSide * kPunctualPointsPerSide) * irradianceSquared);
    for (int c = 0; c < 3; ++c) {
        const double lobe = overSquare(2.0, [&](double x, double z) {
            const glm::dvec3 p(x, 0.0, z), toLight = glm::dvec3(0.0, 1.0, 0.0) - p;
            const double r2 = glm::dot(toLight, toLight);
            return overSquare(1.0, [&](double u, double v) {
                const glm::dvec3 d = glm::dvec3(u, 2.0, v) - p;
                const double d2 = glm::dot(d, d);
                const glm::dvec3 wo = d / std::sqrt(d2);
                return test::ggxReflection(up, wo, toLight / std::sqrt(r2), alpha, f0[c]) *
                       test::ggxEnergy(wo.y, alpha, f0[c]) / r2 * wo.y * wo.y / d2;
            });
        });
        // The albedo at 65 cosines from 1/3 (the floor's corners) to 1, linearly between.
        std::vector<double> albedo(65);
        for (std::size_t k = 0; k < albedo.size(); ++k)
            albedo[k] = test::ggxAlbedo(
                1.0 / 3.0 + (2.0 / 3.0) * k / 64.0, alpha, f0[c],
                [&](const glm::dvec3& wi) { return test::ggxEnergy(wi.z, alpha, f0[c]); }, 300);
        const double kept = overSquare(2.0, [&](double x, double z) {
            const double r = std::sqrt(x * x + z * z + 1.0), at = (1.0 / r - 1.0 / 3.0) / (2.0 / 3.0) * 64.0;
            const std::size_t k = std::min<std::size_t>(63, static_cast<std::size_t>(at));
            const double a = albedo[k] + (at - k) * (albedo[k + 1] - albedo[k]);
            return (1.0 - a) / (r * r * r);
        });
        EXPECT_NEAR(bySpecular[receiver][c], lobe,
                    fiveSigma(lobe, 4.0 * M_PI, static_cast<double>(kPunctualCausticRays)))
            << c;
        EXPECT_NEAR(arrived[metal][c], kept, 5.0 * keptSigma) << c;
        EXPECT_EQ(bySpecular[metal][c], 0.0) << c;
        if (c == 0) {
            RecordProperty("red_received", std::to_string(bySpecular[receiver][c]));
            RecordProperty("red_expected", std::to_string(lobe));
            RecordProperty("red_kept", std::to_string(arrived[metal][c]));
            RecordProperty("red_kept_expected", std::to_string(kept));
        }
    }
}

TEST(SpecularTransport, EnergyBalancesWithARoughMetal) {
    // A lamp over a rough metal floor beside a grey wall (tests/data/specular/): the shots' rays
    // that meet the metal go on with F G2 / G1 (times the energy scale) of their power and leave
    // the rest there (the light its microfacets shadow or absorb), in integers, so emitted =
    // absorbed + escaped + unshot to rounding (a weight above 1 passes on the whole power and
    // leaves none: this checks the bookkeeping with the new
    // kind, not the lobe, which the tests above do). The metal reflects nothing diffusely (its
    // radiosity is 0) and keeps a share of what reaches it (F0 (0.95, 0.8, 0.5): more in blue).
    const TestScene s("tests/data/specular/lamp-over-rough-metal.gltf", 0.1);
    ProgressiveOptions options;
    options.rays = 500'000;
    const ProgressiveResult r = ProgressiveSolver(s, s.elements).solve(options);
    EXPECT_LT(r.energy.relativeResidual(), 1e-6);
    const std::vector<glm::dvec3> means = surfaceMeans(s.mesh(), s.elements, r.radiosity);
    const std::vector<glm::dvec3> power = surfacePower(s, r);
    const std::size_t metal = s.surface("metal");
    for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(means[metal][c], 0.0) << c;
        EXPECT_GT(power[metal][c], 0.0) << c;
    }
    EXPECT_GT(power[metal].z, 2.0 * power[metal].x);
    EXPECT_GT(means[s.surface("wall")].x, 0.0);
}

TEST(SpecularTransportLong, AnyCounterLayoutGivesTheSameBits) {
    const TestScene s("scenes/cornell-box-specular.gltf", 0.1);
    ProgressiveOptions options;
    options.rays = 300'000;
    options.tolerance = 1e-2;
    options.counters = CounterLayout{0, 1};
    const ProgressiveResult reference = ProgressiveSolver(s, s.elements).solve(options);
    ASSERT_GT(reference.tallies.batches, 3u);
    ASSERT_EQ(reference.caustic.size(), reference.incident.size());
    for (const CounterLayout layout : {CounterLayout{2, 1}, CounterLayout{3, 3}}) {
        options.counters = layout;
        const ProgressiveResult other = ProgressiveSolver(s, s.elements).solve(options);
        EXPECT_TRUE(other.radiosity == reference.radiosity) << layout.takers << " takers, " << layout.sets << " sets";
        EXPECT_TRUE(other.incident == reference.incident) << layout.takers << " takers, " << layout.sets << " sets";
        EXPECT_TRUE(other.caustic == reference.caustic) << layout.takers << " takers, " << layout.sets << " sets";
        EXPECT_EQ(other.energy.escaped, reference.energy.escaped);
    }
}

}  // namespace
}  // namespace rad
