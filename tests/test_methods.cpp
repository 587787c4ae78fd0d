// The classic estimators on the device: hemicube, gather and shooting matrices, against closed
// forms and against each other.

#include <cmath>

#include <gtest/gtest.h>

#include "device_fixture.h"
#include "util/analytic_form_factors.h"
#include "formfactor/enforce.h"
#include "formfactor/patch_matrix.h"
#include "formfactor/surface_view_factors.h"
#include "formfactor/view_factor_table.h"
#include "solver/matrix_solvers.h"
#include "solver/progressive_solver.h"
#include "solver/surface_means.h"

namespace rad {
namespace {

using test::TestScene;
using test::sharedCompute;

// The matrix of the registry's estimator `method` with the given options (defaults otherwise).
PatchMatrix matrixOf(const TestScene& s, const std::string& method, const OptionValues& options = {}) {
    return buildPatchMatrix(s, method, options, 1);
}

// F from patch `patch`'s centroid to the surface `target` (a planar polygon given by corners),
// by the closed form, in the mesh's coordinates.
double centreFactor(const Patch& patch, const std::vector<glm::dvec3>& target) {
    const glm::dvec3 c = (glm::dvec3(patch.p[0]) + glm::dvec3(patch.p[1]) + glm::dvec3(patch.p[2])) / 3.0;
    return pointToPolygonFactor(c, glm::dvec3(patch.normal), target);
}

TEST(Methods, HemicubeErrorFallsAsResolutionGrows) {
    // One large patch per triangle: the hemicube row of a bottom patch, summed over the top,
    // against the exact factor from that patch's centre (the hemicube's own approximation).
    const TestScene s("scenes/facing-squares.gltf", 10.0);
    const std::size_t top = s.surface("top");
    std::vector<glm::dvec3> square;
    const glm::dvec3 o = s.scene().origin;
    for (const auto& p : {glm::dvec3(0, 1, 0), glm::dvec3(1, 1, 0), glm::dvec3(1, 1, 1), glm::dvec3(0, 1, 1)}) square.push_back(p - o);
    const std::uint32_t patch = s.mesh().surfaces[s.surface("bottom")].firstPatch;
    const double exact = centreFactor(s.mesh().patches[patch], square);
    std::vector<double> errors;
    for (std::uint32_t r : {8u, 32u, 128u}) {
        const PatchMatrix m = matrixOf(s, "hemicube", {{"--hemicube-res", r}});
        double f = 0.0;
        for (std::uint32_t k = 0; k < s.mesh().surfaces[top].patchCount; ++k)
            f += m.F.at(patch, s.mesh().surfaces[top].firstPatch + k);
        errors.push_back(std::fabs(f - exact));
        EXPECT_NEAR(m.weightSum, 1.0, 0.1 / r);  // the delta form factors sum to 1 up to discretisation
    }
    EXPECT_LT(errors[1], errors[0]);
    EXPECT_LT(errors[2], errors[1]);
    EXPECT_LT(errors[2], 2e-3);
}

TEST(Methods, GatherMatchesClosedFormsWith16ShadowRays) {
    const OptionValues opt{{"--shadow-rays", 16}};
    const TestScene facing("scenes/facing-squares.gltf", 0.2);
    const ViewFactorTable a = surfaceTable(facing.mesh(), matrixOf(facing, "gather", opt));
    EXPECT_NEAR(a.factor(facing.surface("bottom"), facing.surface("top")), parallelSquaresFactor(1, 1), 0.01 * 0.2);
    const TestScene perpendicular("scenes/perpendicular-squares.gltf", 0.2);
    const ViewFactorTable b = surfaceTable(perpendicular.mesh(), matrixOf(perpendicular, "gather", opt));
    EXPECT_NEAR(b.factor(perpendicular.surface("floor"), perpendicular.surface("wall")), perpendicularSquaresFactor(),
                0.01 * 0.2);
}

TEST(MethodsLong, GatherAndHemicubeSeeTheBlocksLikeRaysDo) {
    // Occlusion: the Cornell light's view of the floor is cut by the blocks. Rays measure it
    // to 3e-4 here; gather's visibility and the hemicube's pixels must agree within 2 %.
    const TestScene s("scenes/cornell-box.gltf", 0.12);
    const std::size_t light = s.surface("light"), floor = s.surface("floor");
    const double reference = computeSurfaceViewFactors(s, {1'000'000, 1}).factor(light, floor);
    EXPECT_NEAR(surfaceTable(s.mesh(), matrixOf(s, "gather")).factor(light, floor), reference, 0.02 * reference);
    EXPECT_NEAR(surfaceTable(s.mesh(), matrixOf(s, "hemicube")).factor(light, floor), reference, 0.02 * reference);
}

TEST(Methods, EnforceBothOnAClosedCubeMatrix) {
    const TestScene s("scenes/closed-cube.gltf", 0.3);
    const PatchMatrix m = matrixOf(s, "shoot", {{"--rays-per-patch", 2000}});
    EXPECT_EQ(m.raysPerRow, 2000u);
    ViewFactorTable t = patchTable(s.mesh(), m);
    const EnforceSummary summary = enforce(t, Enforce::Both);
    EXPECT_EQ(summary.closedRows, t.size());  // a closed scene: no ray missed
    for (std::size_t i = 0; i < t.size(); ++i) {
        double sum = 0.0;
        for (const ViewFactorEntry& e : t.rows[i]) {
            ASSERT_GE(e.factor, 0.0);
            sum += e.factor;
            EXPECT_NEAR(t.areas[i] * e.factor, t.areas[e.to] * t.factor(e.to, i), 1e-9 * t.areas[i]);
        }
        EXPECT_NEAR(sum, 1.0, 1e-9);
    }
}

TEST(MethodsLong, EveryMethodAndSolverLightsTheCornellBoxAlike) {
    // Surface radiosities from each estimator with Gauss-Seidel, and from the device's own
    // progressive solver, agree within 3 %: the methods' differences at this mesh.
    const TestScene s("scenes/cornell-box.gltf", 0.1);
    ProgressiveOptions po;
    po.rays = 4'000'000;
    po.tolerance = 1e-4;
    const auto reference = surfaceMeans(s.mesh(), s.elements, ProgressiveSolver(s, s.elements).solve(po).radiosity);
    std::vector<glm::dvec3> e, rho;
    std::vector<double> area;
    const auto exitance = s.patches().exitance();
    for (std::size_t p = 0; p < s.mesh().patches.size(); ++p) {
        e.emplace_back(exitance[p]);
        rho.emplace_back(s.patches().reflectance[p]);
        area.push_back(s.mesh().patches[p].area);
    }
    for (const FormFactorMethod& method : formFactorMethods()) {
        const OptionValues opt{{"--rays-per-patch", 20'000}, {"--shadow-rays", 8}};
        MatrixSolveOptions so;
        so.solver = MatrixSolver::GaussSeidel;
        const auto r = solveMatrix(matrixOf(s, method.name, opt), e, rho, area, so);
        EXPECT_TRUE(r.converged);
        std::vector<glm::vec3> b;
        for (const auto& v : r.radiosity) b.emplace_back(v);
        const auto means = surfaceMeans(s.mesh(), s.elements, b);
        for (std::size_t k = 0; k < means.size(); ++k)
            EXPECT_NEAR(means[k].x, reference[k].x, 0.03 * reference[k].x) << method.name << " " << s.mesh().surfaces[k].name;
        EXPECT_LT(r.energy.relativeResidual(), 0.01) << method.name;
    }
}

}  // namespace
}  // namespace rad
