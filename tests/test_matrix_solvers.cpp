// Full-matrix solvers and view-factor corrections on small synthetic systems, against dense
// linear algebra done here independently.

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "formfactor/enforce.h"
#include "solver/matrix_solvers.h"
#include "util/error.h"

namespace rad {
namespace {

// A random "form-factor" matrix: n patches, each row sparse, non-negative, summing to `closure`.
PatchMatrix randomMatrix(std::uint32_t n, double closure, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    PatchMatrix m;
    m.F.columns = n;
    for (std::uint32_t i = 0; i < n; ++i) {
        std::vector<std::pair<std::uint32_t, float>> row;
        std::vector<double> w;
        double sum = 0.0;
        for (std::uint32_t j = 0; j < n; ++j)
            if (j != i && u(rng) < 0.3) {
                row.emplace_back(j, 0.0f);
                w.push_back(u(rng));
                sum += w.back();
            }
        for (std::size_t k = 0; k < row.size(); ++k) row[k].second = static_cast<float>(closure * w[k] / sum);
        m.F.appendRow(row);
        m.missed.push_back(static_cast<float>(1.0 - closure));
    }
    return m;
}

struct System {
    std::vector<glm::dvec3> e, rho;
    std::vector<double> area;
};

System randomSystem(std::uint32_t n, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    System s;
    for (std::uint32_t i = 0; i < n; ++i) {
        s.e.emplace_back(i % 7 == 0 ? glm::dvec3(u(rng), u(rng), u(rng)) * 10.0 : glm::dvec3(0.0));
        s.rho.emplace_back(0.2 + 0.7 * u(rng), 0.2 + 0.7 * u(rng), 0.2 + 0.7 * u(rng));
        s.area.push_back(0.5 + u(rng));
    }
    return s;
}

TEST(MatrixSolvers, JacobiWithKBouncesIsTheNeumannSeriesToK) {
    const std::uint32_t n = 40;
    const PatchMatrix m = randomMatrix(n, 0.9, 3);
    const System s = randomSystem(n, 4);
    for (int bounces = 1; bounces <= 4; ++bounces) {
        MatrixSolveOptions o;
        o.solver = MatrixSolver::Jacobi;
        o.bounces = bounces;
        const auto r = solveMatrix(m, s.e, s.rho, s.area, o);
        // E + (rho F) E + ... + (rho F)^K E, term by term with dense products.
        std::vector<glm::dvec3> term = s.e, sum = s.e;
        for (int k = 1; k <= bounces; ++k) {
            std::vector<glm::dvec3> next(n, glm::dvec3(0.0));
            for (std::uint32_t i = 0; i < n; ++i)
                for (std::uint32_t j = 0; j < n; ++j) next[i] += s.rho[i] * static_cast<double>(m.F.at(i, j)) * term[j];
            term = next;
            for (std::uint32_t i = 0; i < n; ++i) sum[i] += term[i];
        }
        for (std::uint32_t i = 0; i < n; ++i)
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(r.radiosity[i][c], sum[i][c], 1e-12 * (1.0 + sum[i][c])) << bounces;
        EXPECT_EQ(r.iterations, static_cast<std::uint64_t>(bounces));
    }
}

TEST(MatrixSolvers, DirectGaussSeidelAndProgressiveAgree) {
    const std::uint32_t n = 300;
    const PatchMatrix m = randomMatrix(n, 0.95, 5);
    const System s = randomSystem(n, 6);
    MatrixSolveOptions o;
    o.solver = MatrixSolver::Direct;
    const auto direct = solveMatrix(m, s.e, s.rho, s.area, o);
    o.solver = MatrixSolver::GaussSeidel;
    o.tolerance = 1e-8;
    const auto gs = solveMatrix(m, s.e, s.rho, s.area, o);
    o.solver = MatrixSolver::Progressive;
    o.tolerance = 1e-6;
    const auto progressive = solveMatrix(m, s.e, s.rho, s.area, o);
    o.solver = MatrixSolver::Jacobi;
    o.tolerance = 1e-10;
    const auto jacobi = solveMatrix(m, s.e, s.rho, s.area, o);
    EXPECT_LT(direct.residual, 1e-12);
    EXPECT_TRUE(gs.converged);
    EXPECT_TRUE(progressive.converged);
    EXPECT_TRUE(jacobi.converged);
    double scale = 0.0;
    for (const auto& b : direct.radiosity) scale = std::max({scale, b.x, b.y, b.z});
    for (std::uint32_t i = 0; i < n; ++i)
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(gs.radiosity[i][c], direct.radiosity[i][c], 1e-5 * scale);
            EXPECT_NEAR(progressive.radiosity[i][c], direct.radiosity[i][c], 1e-5 * scale);
            EXPECT_NEAR(jacobi.radiosity[i][c], direct.radiosity[i][c], 1e-5 * scale);
        }
}

TEST(MatrixSolvers, DirectRefusesASystemBeyondMaxMemory) {
    const PatchMatrix m = randomMatrix(200, 0.9, 7);
    const System s = randomSystem(200, 8);
    MatrixSolveOptions o;
    o.solver = MatrixSolver::Direct;
    o.maxMemory = 100'000;  // 200^2 doubles twice is 640 kB
    try {
        solveMatrix(m, s.e, s.rho, s.area, o);
        FAIL() << "a system beyond --max-memory was solved";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("MiB"), std::string::npos) << e.what();
    }
}

ViewFactorTable tableOf(const PatchMatrix& m, const std::vector<double>& area) {
    ViewFactorTable t;
    for (std::uint32_t i = 0; i < m.F.rows(); ++i) {
        t.names.push_back("p" + std::to_string(i));
        t.areas.push_back(area[i]);
        t.rows.emplace_back();
        for (std::uint64_t k = m.F.rowStart[i]; k < m.F.rowStart[i + 1]; ++k) t.rows.back().push_back({m.F.column[k], m.F.value[k]});
        t.missed.push_back(m.missed[i]);
    }
    return t;
}

TEST(Enforce, BothGivesSymmetricClosedNonNegativeFactors) {
    // Closed rows with noise (sums 0.97 .. 1.03) and unequal areas: nothing reciprocal yet.
    const std::uint32_t n = 60;
    PatchMatrix m = randomMatrix(n, 1.0, 9);
    std::mt19937 rng(10);
    std::uniform_real_distribution<float> noise(0.97f, 1.03f);
    for (float& v : m.F.value) v *= noise(rng);
    for (float& missed : m.missed) missed = 0.0f;
    const System s = randomSystem(n, 11);
    ViewFactorTable t = tableOf(m, s.area);
    const EnforceSummary summary = enforce(t, Enforce::Both);
    EXPECT_EQ(summary.closedRows, n);
    EXPECT_GT(summary.largestChange, 0.0);
    for (std::uint32_t i = 0; i < n; ++i) {
        double sum = 0.0;
        for (const ViewFactorEntry& e : t.rows[i]) {
            EXPECT_GE(e.factor, 0.0);
            sum += e.factor;
            const double gij = t.areas[i] * e.factor, gji = t.areas[e.to] * t.factor(e.to, i);
            EXPECT_NEAR(gij, gji, 1e-9 * std::max(1.0, gij));
        }
        EXPECT_NEAR(sum, 1.0, 1e-9);
    }
}

TEST(Enforce, ReciprocityAloneAndClosureAlone) {
    const std::uint32_t n = 30;
    PatchMatrix m = randomMatrix(n, 1.0, 12);
    for (float& missed : m.missed) missed = 0.0f;
    const System s = randomSystem(n, 13);
    ViewFactorTable symmetric = tableOf(m, s.area);
    enforce(symmetric, Enforce::Reciprocity);
    for (std::uint32_t i = 0; i < n; ++i)
        for (const ViewFactorEntry& e : symmetric.rows[i])
            EXPECT_NEAR(symmetric.areas[i] * e.factor, symmetric.areas[e.to] * symmetric.factor(e.to, i), 1e-12);
    ViewFactorTable closed = tableOf(m, s.area);
    for (auto& row : closed.rows)
        for (auto& e : row) e.factor *= 0.9;  // rows now sum to 0.9
    enforce(closed, Enforce::Closure);
    for (std::uint32_t i = 0; i < n; ++i) {
        double sum = 0.0;
        for (const ViewFactorEntry& e : closed.rows[i]) sum += e.factor;
        EXPECT_NEAR(sum, 1.0, 1e-12);
    }
}


// Two open surface rows ("small", "large") that see each other, each estimated from `rays`
// independent rays (F and its binomial standard error); open, so nothing is scaled to close.
ViewFactorTable binomialPair(double smallArea, double largeArea, double fs, double fl, std::uint32_t rays) {
    ViewFactorTable t;
    t.names = {"small", "large"};
    t.areas = {smallArea, largeArea};
    t.rows = {{{1, fs, std::sqrt(fs * (1 - fs) / rays)}}, {{0, fl, std::sqrt(fl * (1 - fl) / rays)}}};
    t.missed = {1 - fs, 1 - fl};
    t.rays = {double(rays), double(rays)};
    return t;
}

// Two surfaces of very unequal area (1 and 100 m^2) that see each other by G = A_i F_ij = 0.5
// m^2, each row estimated from the same number of independent rays, as `viewfactors` shoots
// them. Both rows estimate G, but the small one much better: its F is 0.5, binomial noise
// sqrt(0.25 / N); the large row's F of 0.005 carries sqrt(0.005 / N), times 100 in G. Over many
// independent estimates, the corrected small-to-large factor must spread no more than its own
// estimate did (an equal-weight average spreads seven times as much) and as its reported
// standard error says: the mean of z^2 is 1 within its sampling noise.
TEST(Enforce, ReciprocityWeighsTheRowWithTheDenserRays) {
    const double smallArea = 1.0, largeArea = 100.0, g = 0.5;
    const std::uint32_t rays = 20000, trials = 2000;
    std::mt19937_64 rng(17);
    std::binomial_distribution<std::uint32_t> fromSmall(rays, g / smallArea), fromLarge(rays, g / largeArea);
    double rawSquares = 0.0, correctedSquares = 0.0, zSquares = 0.0, reciprocityGap = 0.0;
    for (std::uint32_t k = 0; k < trials; ++k) {
        const double fs = static_cast<double>(fromSmall(rng)) / rays, fl = static_cast<double>(fromLarge(rng)) / rays;
        ViewFactorTable t = binomialPair(smallArea, largeArea, fs, fl, rays);
        enforce(t, Enforce::Reciprocity);
        const ViewFactorEntry& e = t.rows[0][0];
        const double exact = g / smallArea;
        rawSquares += (fs - exact) * (fs - exact);
        correctedSquares += (e.factor - exact) * (e.factor - exact);
        zSquares += (e.factor - exact) * (e.factor - exact) / (e.standardError * e.standardError);
        reciprocityGap = std::max(reciprocityGap, std::fabs(smallArea * e.factor - largeArea * t.rows[1][0].factor));
    }
    EXPECT_LT(reciprocityGap, 1e-12);
    // Variances estimated from 2000 trials: relative noise sqrt(2 / 2000) = 3 %; 5 sigma.
    const double tolerance = 5.0 * std::sqrt(2.0 / trials);
    EXPECT_LT(correctedSquares / rawSquares, 1.0 + tolerance);
    EXPECT_NEAR(zSquares / trials, 1.0, tolerance);
}

// Two estimates of one G from rows of unequal binomial variance in a way the (1 - F) factor
// decides: a small surface almost enclosed by a larger one (areas 1 and 2, G = 0.9, so F = 0.9
// and 0.45). Row variances of G: 0.09 / N and 0.99 / N; their best combination has variance
// 1 / (1 / 0.09 + 1 / 0.99) = 0.0825 / N. Weights without the (1 - F) factor (1 and 0.5) would
// give 0.15 / N. The corrected small-to-large factor must spread as the best combination does,
// and its standard error must say so (mean z^2 = 1).
TEST(Enforce, ReciprocityWeighsByTheBinomialVarianceIncludingOneMinusF) {
    const double smallArea = 1.0, largeArea = 2.0, g = 0.9;
    const std::uint32_t rays = 20000, trials = 2000;
    std::mt19937_64 rng(23);
    std::binomial_distribution<std::uint32_t> fromSmall(rays, g / smallArea), fromLarge(rays, g / largeArea);
    double squares = 0.0, zSquares = 0.0;
    for (std::uint32_t k = 0; k < trials; ++k) {
        const double fs = static_cast<double>(fromSmall(rng)) / rays, fl = static_cast<double>(fromLarge(rng)) / rays;
        ViewFactorTable t = binomialPair(smallArea, largeArea, fs, fl, rays);
        enforce(t, Enforce::Reciprocity);
        const ViewFactorEntry& e = t.rows[0][0];
        squares += (e.factor - g) * (e.factor - g) / trials;
        zSquares += (e.factor - g) * (e.factor - g) / (e.standardError * e.standardError) / trials;
    }
    const double best = 1.0 / (1.0 / 0.09 + 1.0 / 0.99) / rays;  // smallArea = 1: G and F alike
    const double tolerance = 5.0 * std::sqrt(2.0 / trials);
    EXPECT_NEAR(squares / best, 1.0, tolerance);
    EXPECT_NEAR(zSquares, 1.0, tolerance);
}

// Equal areas and rays: the two estimates count alike, and the standard error written is that of
// their mean, sqrt(F (1 - F) / 2N) at the combined F. After `both` on closed rows the entries and
// their errors are scaled alike (d_i d_j).
TEST(Enforce, StandardErrorsOfTheCombinationAndOfTheScaledEntries) {
    ViewFactorTable t;
    t.names = {"a", "b", "c"};
    t.areas = {1.0, 1.0, 1.0};
    const double n = 10000;
    auto se = [&](double f) { return std::sqrt(f * (1 - f) / n); };
    t.rows = {{{1, 0.30, se(0.30)}, {2, 0.68, se(0.68)}},
              {{0, 0.34, se(0.34)}, {2, 0.65, se(0.65)}},
              {{0, 0.70, se(0.70)}, {1, 0.31, se(0.31)}}};
    t.missed = {0.02, 0.01, -0.01};
    t.rays = {n, n, n};
    ViewFactorTable reciprocal = t;
    enforce(reciprocal, Enforce::Reciprocity);
    const double f01 = (0.30 + 0.34) / 2;
    EXPECT_NEAR(reciprocal.factor(0, 1), f01, 1e-15);
    EXPECT_NEAR(reciprocal.rows[0][0].standardError, std::sqrt(f01 * (1 - f01) / (2 * n)), 1e-15);
    ViewFactorTable both = t;
    both.missed = {0.0, 0.0, 0.0};  // closed rows: scaled to sum 1
    enforce(both, Enforce::Both);
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t k = 0; k < 2; ++k) {
            const ViewFactorEntry &r = reciprocal.rows[i][k], &b = both.rows[i][k];
            ASSERT_EQ(r.to, b.to);
            EXPECT_NE(b.factor, r.factor);  // the scale did something
            EXPECT_NEAR(b.standardError / r.standardError, b.factor / r.factor, 1e-12);
        }
}

// Without ray counts (hemicube, gather) the correction is the plain symmetric average.
TEST(Enforce, ReciprocityWithoutRaysIsTheSymmetricAverage) {
    ViewFactorTable t;
    t.names = {"a", "b"};
    t.areas = {1.0, 4.0};
    t.rows = {{{1, 0.5}}, {{0, 0.1}}};
    t.missed = {0.5, 0.9};
    enforce(t, Enforce::Reciprocity);
    EXPECT_NEAR(t.rows[0][0].factor, (0.5 + 4.0 * 0.1) / 2.0, 1e-15);
    EXPECT_NEAR(t.rows[1][0].factor, (0.5 + 4.0 * 0.1) / 2.0 / 4.0, 1e-15);
    EXPECT_TRUE(std::isnan(t.rows[0][0].standardError));
}

}  // namespace
}  // namespace rad
