// The matrix strategy: the whole patch-to-patch form-factor matrix by the chosen estimator
// (formfactor/estimator.h), then the chosen matrix solver (matrix_solvers.h), one element per
// patch. Takes every --method and --solver the device strategy does not.

#include <algorithm>
#include <cstdio>

#include "formfactor/estimator.h"
#include "formfactor/patch_matrix.h"
#include "prepared/prepared_scene.h"
#include "solver/direct_light.h"
#include "solver/matrix_solvers.h"
#include "solver/progressive_options.h"
#include "solver/solve_strategy.h"
#include "util/error.h"

namespace rad {
namespace {

class MatrixPath : public SolveStrategy {
public:
    explicit MatrixPath(const SolveChoice& choice)
        : method_(formFactorMethod(choice.method)),
          solver_(matrixSolverNamed(choice.solver)),
          values_(choice.values),
          seed_(choice.seed) {}

    std::vector<OptionSpec> options() const override {
        std::vector<OptionSpec> all{kMaxMemoryOption};
        all.insert(all.end(), method_.options.begin(), method_.options.end());
        all.insert(all.end(), solver_.options.begin(), solver_.options.end());
        return all;
    }

    void check(const PreparedScene& scene, const SolveControl& control) const override {
        if (!control.warn) return;
        for (const std::string& w : method_.reliability(scene.mesh(), values_)) control.warn(w);
        // Form factors are between diffuse patches: only the progressive solve's shots carry
        // light through mirrors and glass (kernels/shoot.cl).
        if (scene.device().specularFaces())
            control.warn("the scene has mirrors or glass: --method " + method_.name + " --solver " + solver_.name +
                         " reflects a mirror's light diffusely and takes glass as opaque; --method shoot "
                         "--solver progressive carries light through them");
    }

    Solution solve(const PreparedScene& scene, const SolveControl& control) override {
        const Mesh& mesh = scene.mesh();
        MatrixSolveOptions solve;
        solve.solver = solver_.solver;
        // Each solver's own options only (matrix_solvers.cpp declares them).
        if (solve.solver == MatrixSolver::Jacobi) solve.bounces = static_cast<int>(values_.count32(kBouncesOption));
        if (solve.solver == MatrixSolver::Progressive) solve.tolerance = values_.number(kToleranceOption);
        if (solve.solver == MatrixSolver::Jacobi || solve.solver == MatrixSolver::GaussSeidel)
            solve.tolerance = values_.number(kResidualOption);
        solve.maxMemory = values_.count64(kMaxMemoryOption);
        // The direct solver's dense system is refused before the matrix is built, not after.
        const double denseBytes =
            16.0 * static_cast<double>(mesh.patches.size()) * static_cast<double>(mesh.patches.size());
        if (solve.solver == MatrixSolver::Direct && denseBytes > static_cast<double>(solve.maxMemory))
            throw InputError("the direct solver needs a dense " + std::to_string(mesh.patches.size()) + " x " +
                             std::to_string(mesh.patches.size()) + " system: about " +
                             std::to_string(static_cast<std::uint64_t>(denseBytes / (1 << 20))) +
                             " MiB; --max-memory allows " + std::to_string(solve.maxMemory >> 20) +
                             " MiB (use --solver gauss-seidel, or a larger --patch-size)");
        const auto estimator = method_.create(scene, values_, seed_);
        const PatchMatrix matrix =
            buildPatchMatrix(*estimator, static_cast<std::uint32_t>(mesh.patches.size()), solve.maxMemory, method_.name,
                             control.group ? *control.group : oneProcess());

        Solution s;
        s.elements = ElementMesh::uniform(mesh, 0.0);  // one per patch, in patch order
        const PatchSystem& system = scene.patches();
        const std::vector<glm::vec3> e = system.exitance();
        std::vector<glm::dvec3> exitance, reflectance;
        std::vector<double> area;
        for (std::size_t p = 0; p < system.size(); ++p) {
            exitance.emplace_back(e[p]);
            reflectance.emplace_back(system.reflectance[p]);
            area.push_back(system.area[p]);
        }
        // Direct light from emitters that are not shot (light/emitter.h): what a patch reflects
        // of it leaves the patch like emitted light. Mirrors and glass as these solvers model
        // them (diffuse, opaque), so that a mirror does not both reflect diffusely and pass on.
        const DirectLight direct = directLight(scene, s.elements, seed_, SpecularModel::diffuse);
        if (!direct.empty())
            for (std::size_t p = 0; p < area.size(); ++p)
                if (area[p] > 0.0) exitance[p] += reflectance[p] * direct.arrived[p] / area[p];

        const MatrixSolveResult result = solveMatrix(matrix, exitance, reflectance, area, solve);
        for (const glm::dvec3& b : result.radiosity) s.radiosity.emplace_back(b);
        // H = (B - E) / rho where the patch reflects; a black patch shows no reflected light.
        for (std::size_t p = 0; p < result.radiosity.size(); ++p) {
            glm::dvec3 h(0.0);
            for (int c = 0; c < 3; ++c)
                if (reflectance[p][c] > 0.0)
                    h[c] = std::max(0.0, (result.radiosity[p][c] - e[p][c]) / reflectance[p][c]);
            s.irradiance.emplace_back(h);
        }
        s.energy = result.energy;
        if (!direct.empty()) {
            // The balance counted the reflected part of the direct light as emitted; the rest
            // was emitted too, and absorbed where it arrived, or it escaped.
            glm::dvec3 absorbed(0.0);
            for (std::size_t p = 0; p < area.size(); ++p)
                absorbed += (glm::dvec3(1.0) - reflectance[p]) * direct.arrived[p];
            s.energy.emitted += absorbed + direct.absorbedByBacks + direct.escaped;
            s.energy.absorbed += absorbed + direct.absorbedByBacks;
            s.energy.absorbedByBacks += direct.absorbedByBacks;
            s.energy.escaped += direct.escaped;
        }
        s.iterations = result.iterations;
        s.residual = result.residual;
        s.stopped = solve.bounces > 0 && solve.solver == MatrixSolver::Jacobi ? "bounces"
                    : result.converged                                        ? "tolerance"
                                                                              : "max-iterations";
        if (solve.solver == MatrixSolver::Progressive) {
            s.unshotFraction = result.residual;
            s.tallies.shots = result.iterations;
        }
        s.parameters = estimator->reportParameters(matrix);
        if (solve.solver == MatrixSolver::Jacobi) s.parameters.emplace_back("bounces", solve.bounces);
        if (solve.solver == MatrixSolver::Jacobi || solve.solver == MatrixSolver::GaussSeidel)
            s.parameters.emplace_back("residual_tolerance", solve.tolerance);
        s.parameters.emplace_back("matrix_nonzeros", static_cast<double>(matrix.F.nonZeros()));
        char summary[128];
        if (solve.solver == MatrixSolver::Progressive)
            std::snprintf(summary, sizeof summary, "%llu shots, unshot %.2e", static_cast<unsigned long long>(s.tallies.shots),
                          s.unshotFraction);
        else
            std::snprintf(summary, sizeof summary, "%s %s, %llu iterations, residual %.2e", method_.name.c_str(),
                          solver_.name.c_str(), static_cast<unsigned long long>(s.iterations), s.residual);
        s.summary = summary;
        return s;
    }

private:
    const FormFactorMethod& method_;
    const MatrixSolverEntry& solver_;
    OptionValues values_;
    std::uint32_t seed_;
};

}  // namespace

SolveStrategyEntry matrixStrategy() {
    return {"matrix",
            "the whole form-factor matrix by the chosen method, then the chosen matrix solver, per patch",
            "solves on the whole matrix (a --method other than shoot, or a --solver other than progressive)",
            {kMaxMemoryOption},
            [](const std::string& method, const std::string& solver) {
                for (const FormFactorMethod& m : formFactorMethods())
                    for (const MatrixSolverEntry& s : matrixSolvers())
                        if (m.name == method && s.name == solver) return true;
                return false;
            },
            [](const SolveChoice& choice) -> std::unique_ptr<SolveStrategy> {
                if (choice.solver == "progressive" && choice.values.number(kToleranceOption) <= 0.0)
                    throw InputError(
                        "--tolerance 0 never stops by itself: the progressive solver on the matrix needs a "
                        "positive --tolerance");
                return std::make_unique<MatrixPath>(choice);
            }};
}

}  // namespace rad
