#pragma once
// Solvers of the radiosity system B = E + rho F B (per channel) on a whole form-factor matrix:
//   jacobi       B <- E + rho F B from B = E. With K bounces it stops after K steps, giving
//                E + rho F E + ... + (rho F)^K E: K = 1 is direct light only. Otherwise it
//                runs until the residual falls below the tolerance.
//   gauss-seidel the same update patch by patch, each using the newest values; to tolerance.
//   direct       (I - rho F) B = E by dense LU (Eigen): the exact solution of the discrete
//                system, for small scenes; the memory guard refuses large ones.
//   progressive  shooting on the matrix (power form, the strongest unshot patch first), to an
//                unshot fraction; the same algorithm as the device's, on the same form factors.
// The residual is max_i |E_i + rho_i (F B)_i - B_i| / max_i B_i, over channels.

#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "formfactor/patch_matrix.h"
#include "solver/energy_balance.h"
#include "util/options.h"

namespace rad {

enum class MatrixSolver { Jacobi, GaussSeidel, Direct, Progressive };

// --bounces (jacobi) and --residual (jacobi, gauss-seidel); progressive reads --tolerance
// (progressive_options.h).
extern const OptionSpec kBouncesOption;
extern const OptionSpec kResidualOption;

// The --solver registry: each solver's name, description and the options it reads. The names
// are also what the device strategy answers to ("progressive" with --method shoot).
struct MatrixSolverEntry {
    std::string name;
    std::string description;
    std::vector<OptionSpec> options;
    MatrixSolver solver;
};
const std::vector<MatrixSolverEntry>& matrixSolvers();
const MatrixSolverEntry& matrixSolverNamed(const std::string& name);  // InputError naming the choices

struct MatrixSolveOptions {
    MatrixSolver solver = MatrixSolver::GaussSeidel;
    int bounces = 0;                  // jacobi: stop after this many steps (0: to tolerance)
    double tolerance = 1e-6;          // residual (jacobi, gauss-seidel) or unshot fraction (progressive)
    std::uint64_t maxIterations = 100000;
    std::uint64_t maxMemory = 4ull << 30;  // direct: the dense matrix must fit
};

struct MatrixSolveResult {
    std::vector<glm::dvec3> radiosity;   // B per patch
    std::uint64_t iterations = 0;        // sweeps, or shots for progressive
    double residual = 0.0;
    bool converged = false;
    EnergyBalance energy;                // its residual measures the form factors' reciprocity
};

// exitance: E per patch (W/m^2); reflectance: rho per patch; area per patch (m^2).
MatrixSolveResult solveMatrix(const PatchMatrix& matrix, const std::vector<glm::dvec3>& exitance,
                              const std::vector<glm::dvec3>& reflectance, const std::vector<double>& area,
                              const MatrixSolveOptions& options);

// max_i |E_i + rho_i (F B)_i - B_i| / max_i B_i over channels.
double radiosityResidual(const SparseMatrix& F, const std::vector<glm::dvec3>& exitance,
                         const std::vector<glm::dvec3>& reflectance, const std::vector<glm::dvec3>& radiosity);

}  // namespace rad
