#include "solver/matrix_solvers.h"

#include <algorithm>
#include <cmath>
#include <queue>

#include <Eigen/Dense>

#include "solver/progressive_options.h"
#include "util/error.h"

namespace rad {
namespace {

glm::dvec3 rowTimes(const SparseMatrix& F, std::uint32_t i, const std::vector<glm::dvec3>& b) {
    glm::dvec3 sum(0.0);
    for (std::uint64_t k = F.rowStart[i]; k < F.rowStart[i + 1]; ++k) sum += static_cast<double>(F.value[k]) * b[F.column[k]];
    return sum;
}

double largest(const std::vector<glm::dvec3>& b) {
    double m = 0.0;
    for (const glm::dvec3& v : b) m = std::max({m, std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
    return m;
}

std::vector<glm::dvec3> jacobiStep(const SparseMatrix& F, const std::vector<glm::dvec3>& e,
                                   const std::vector<glm::dvec3>& rho, const std::vector<glm::dvec3>& b) {
    std::vector<glm::dvec3> next(b.size());
    for (std::uint32_t i = 0; i < F.rows(); ++i) next[i] = e[i] + rho[i] * rowTimes(F, i, b);
    return next;
}

MatrixSolveResult jacobi(const PatchMatrix& m, const std::vector<glm::dvec3>& e, const std::vector<glm::dvec3>& rho,
                         const MatrixSolveOptions& o) {
    MatrixSolveResult r;
    r.radiosity = e;
    while (r.iterations < o.maxIterations) {
        if (o.bounces > 0 && r.iterations >= static_cast<std::uint64_t>(o.bounces)) break;
        std::vector<glm::dvec3> next = jacobiStep(m.F, e, rho, r.radiosity);
        ++r.iterations;
        double change = 0.0;
        for (std::size_t i = 0; i < next.size(); ++i) {
            const glm::dvec3 d = glm::abs(next[i] - r.radiosity[i]);
            change = std::max({change, d.x, d.y, d.z});
        }
        r.radiosity = std::move(next);
        // For Jacobi the step is the residual of the previous iterate; the true one is taken below.
        if (o.bounces == 0 && change <= o.tolerance * largest(r.radiosity)) break;
    }
    r.residual = radiosityResidual(m.F, e, rho, r.radiosity);
    r.converged = o.bounces > 0 || r.residual <= o.tolerance;
    return r;
}

MatrixSolveResult gaussSeidel(const PatchMatrix& m, const std::vector<glm::dvec3>& e, const std::vector<glm::dvec3>& rho,
                              const MatrixSolveOptions& o) {
    MatrixSolveResult r;
    r.radiosity = e;
    while (r.iterations < o.maxIterations) {
        for (std::uint32_t i = 0; i < m.F.rows(); ++i) r.radiosity[i] = e[i] + rho[i] * rowTimes(m.F, i, r.radiosity);
        ++r.iterations;
        r.residual = radiosityResidual(m.F, e, rho, r.radiosity);
        if (r.residual <= o.tolerance) break;
    }
    r.converged = r.residual <= o.tolerance;
    return r;
}

MatrixSolveResult direct(const PatchMatrix& m, const std::vector<glm::dvec3>& e, const std::vector<glm::dvec3>& rho,
                         const MatrixSolveOptions& o) {
    const std::size_t n = m.F.rows();
    const double bytes = 8.0 * static_cast<double>(n) * static_cast<double>(n) * 2.0;  // the matrix and its LU
    if (bytes > static_cast<double>(o.maxMemory))
        throw InputError("the direct solver needs a dense " + std::to_string(n) + " x " + std::to_string(n) +
                         " system: about " + std::to_string(static_cast<std::uint64_t>(bytes / (1 << 20))) +
                         " MiB; --max-memory allows " + std::to_string(o.maxMemory >> 20) +
                         " MiB (use --solver gauss-seidel, or fewer patches)");
    MatrixSolveResult r;
    r.radiosity.assign(n, glm::dvec3(0.0));
    for (int c = 0; c < 3; ++c) {
        Eigen::MatrixXd a = Eigen::MatrixXd::Identity(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
        Eigen::VectorXd rhs(static_cast<Eigen::Index>(n));
        for (std::uint32_t i = 0; i < n; ++i) {
            rhs[i] = e[i][c];
            for (std::uint64_t k = m.F.rowStart[i]; k < m.F.rowStart[i + 1]; ++k)
                a(i, m.F.column[k]) -= rho[i][c] * static_cast<double>(m.F.value[k]);
        }
        const Eigen::VectorXd b = a.partialPivLu().solve(rhs);
        for (std::uint32_t i = 0; i < n; ++i) r.radiosity[i][c] = b[i];
    }
    r.iterations = 1;
    r.residual = radiosityResidual(m.F, e, rho, r.radiosity);
    r.converged = true;
    return r;
}

// Column i of F as (j, F_ji) lists: who gathers from i.
std::vector<std::vector<std::pair<std::uint32_t, float>>> columns(const SparseMatrix& F) {
    std::vector<std::vector<std::pair<std::uint32_t, float>>> c(F.columns);
    for (std::uint32_t j = 0; j < F.rows(); ++j)
        for (std::uint64_t k = F.rowStart[j]; k < F.rowStart[j + 1]; ++k) c[F.column[k]].emplace_back(j, F.value[k]);
    return c;
}

// Progressive refinement on the matrix, strongest unshot power first. Each receiver j takes
// rho_j F_ji dB_i from shooter i's unshot radiosity dB_i: Southwell relaxation of the same
// system B = E + rho F B the other solvers solve. (Shooting with F_ij A_i / A_j instead is the
// same only where the estimates obey reciprocity exactly.)
MatrixSolveResult progressive(const PatchMatrix& m, const std::vector<glm::dvec3>& e, const std::vector<glm::dvec3>& rho,
                              const std::vector<double>& area, const MatrixSolveOptions& o) {
    const std::size_t n = m.F.rows();
    const auto gatherers = columns(m.F);
    MatrixSolveResult r;
    r.radiosity = e;
    std::vector<glm::dvec3> unshot(n);
    double emitted = 0.0, left = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        unshot[i] = e[i] * area[i];
        emitted += unshot[i].x + unshot[i].y + unshot[i].z;
    }
    left = emitted;
    // A max-heap of (unshot power, patch) with lazy deletion of stale entries.
    using Entry = std::pair<double, std::uint32_t>;
    std::priority_queue<Entry> heap;
    auto total = [&](std::uint32_t i) { return unshot[i].x + unshot[i].y + unshot[i].z; };
    for (std::uint32_t i = 0; i < n; ++i)
        if (total(i) > 0.0) heap.emplace(total(i), i);
    while (r.iterations < o.maxIterations && emitted > 0.0 && left / emitted > o.tolerance && !heap.empty()) {
        const auto [power, i] = heap.top();
        heap.pop();
        if (power != total(i)) continue;  // stale
        const glm::dvec3 shot = area[i] > 0.0 ? unshot[i] / area[i] : glm::dvec3(0.0);  // unshot radiosity
        unshot[i] = glm::dvec3(0.0);
        left -= power;
        for (const auto& [j, fji] : gatherers[i]) {
            const glm::dvec3 gained = rho[j] * static_cast<double>(fji) * shot;
            r.radiosity[j] += gained;
            unshot[j] += gained * area[j];
            left += (gained.x + gained.y + gained.z) * area[j];
            if (total(j) > 0.0) heap.emplace(total(j), j);
        }
        ++r.iterations;
    }
    r.residual = emitted > 0.0 ? left / emitted : 0.0;  // the unshot fraction
    r.converged = r.residual <= o.tolerance;
    return r;
}

// Where the power went, from a solution: what leaves patch i is B_i A_i; of it F_ij reaches j,
// `missed` reaches nothing; of what arrives at j, (1 - rho_j) is absorbed. "Unshot" is what the
// solution has not yet carried: A_j (E_j + rho_j (F B)_j - B_j), zero when B solves the system,
// the next bounce's light after a Jacobi bounce limit. The balance then closes only as well as
// the estimated form factors obey reciprocity (A_i F_ij = A_j F_ji) and the rows their sums:
// its residual measures those estimates.
EnergyBalance balance(const PatchMatrix& m, const std::vector<glm::dvec3>& e, const std::vector<glm::dvec3>& rho,
                      const std::vector<double>& area, const std::vector<glm::dvec3>& b) {
    EnergyBalance energy;
    std::vector<glm::dvec3> arriving(b.size(), glm::dvec3(0.0));
    for (std::uint32_t i = 0; i < m.F.rows(); ++i) {
        const glm::dvec3 leaving = b[i] * area[i];
        energy.emitted += e[i] * area[i];
        energy.escaped += leaving * static_cast<double>(m.missed[i]);
        energy.unshot += (e[i] + rho[i] * rowTimes(m.F, i, b) - b[i]) * area[i];
        for (std::uint64_t k = m.F.rowStart[i]; k < m.F.rowStart[i + 1]; ++k)
            arriving[m.F.column[k]] += leaving * static_cast<double>(m.F.value[k]);
    }
    for (std::size_t j = 0; j < b.size(); ++j) energy.absorbed += (glm::dvec3(1.0) - rho[j]) * arriving[j];
    return energy;
}

}  // namespace

const OptionSpec kBouncesOption = OptionSpec::count("--bounces", "jacobi: stop after this many bounces (1: direct light only; 0: to --residual)", 0, 0, 1e6);
const OptionSpec kResidualOption = OptionSpec::positive("--residual", "jacobi, gauss-seidel: stop when the residual falls below this", 1e-6);

const std::vector<MatrixSolverEntry>& matrixSolvers() {
    static const std::vector<MatrixSolverEntry> solvers = {
        {"progressive",
         "progressive refinement, strongest unshot power first: on the device with --method shoot, on the whole "
         "matrix with the other methods",
         {kToleranceOption}, MatrixSolver::Progressive},
        {"jacobi", "B <- E + rho F B from B = E on the whole matrix, to a residual or a number of bounces",
         {kBouncesOption, kResidualOption}, MatrixSolver::Jacobi},
        {"gauss-seidel", "the same update patch by patch with the newest values, to a residual", {kResidualOption},
         MatrixSolver::GaussSeidel},
        {"direct", "(I - rho F) B = E by dense LU: the exact solution of the discrete system, for small scenes", {},
         MatrixSolver::Direct},
    };
    return solvers;
}

const MatrixSolverEntry& matrixSolverNamed(const std::string& name) {
    std::string choices;
    for (const MatrixSolverEntry& s : matrixSolvers()) {
        if (s.name == name) return s;
        choices += (choices.empty() ? "" : ", ") + s.name;
    }
    throw InputError("--solver " + name + ": use one of " + choices);
}

double radiosityResidual(const SparseMatrix& F, const std::vector<glm::dvec3>& exitance,
                         const std::vector<glm::dvec3>& reflectance, const std::vector<glm::dvec3>& radiosity) {
    double worst = 0.0;
    for (std::uint32_t i = 0; i < F.rows(); ++i) {
        const glm::dvec3 d = glm::abs(exitance[i] + reflectance[i] * rowTimes(F, i, radiosity) - radiosity[i]);
        worst = std::max({worst, d.x, d.y, d.z});
    }
    const double scale = largest(radiosity);
    return scale > 0.0 ? worst / scale : worst;
}

MatrixSolveResult solveMatrix(const PatchMatrix& matrix, const std::vector<glm::dvec3>& exitance,
                              const std::vector<glm::dvec3>& reflectance, const std::vector<double>& area,
                              const MatrixSolveOptions& options) {
    MatrixSolveResult r;
    switch (options.solver) {
        case MatrixSolver::Jacobi: r = jacobi(matrix, exitance, reflectance, options); break;
        case MatrixSolver::GaussSeidel: r = gaussSeidel(matrix, exitance, reflectance, options); break;
        case MatrixSolver::Direct: r = direct(matrix, exitance, reflectance, options); break;
        case MatrixSolver::Progressive: r = progressive(matrix, exitance, reflectance, area, options); break;
    }
    r.energy = balance(matrix, exitance, reflectance, area, r.radiosity);
    return r;
}

}  // namespace rad
