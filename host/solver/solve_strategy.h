#pragma once
// Solve strategies: every way of solving the radiosity system behind one interface, returning
// one Solution (docs/architecture.md, "How to add"). Two today:
//   device-progressive (progressive_strategy.cpp): progressive refinement resident on the
//       device, patches shooting rays, elements receiving (two levels, adaptive refinement,
//       checkpoints); the default, for --method shoot --solver progressive;
//   matrix (matrix_strategy.cpp): the whole form-factor matrix by any estimator (estimator.h),
//       then a matrix solver (matrix_solvers.h), per patch.
// The registry (solve_strategies.cpp) picks the first strategy that takes the chosen --method
// and --solver. A strategy declares every option it reads (its own, and for the matrix
// strategy its estimator's and matrix solver's), so the command line refuses the others.

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>

#include "mesh/elements.h"
#include "solver/energy_balance.h"
#include "solver/progressive_solver.h"
#include "solver/solver_state.h"
#include "util/options.h"

namespace rad {

class PreparedScene;

// What every strategy produces.
struct Solution {
    ElementMesh elements;              // the receivers the radiosity is given on
    std::vector<glm::vec3> radiosity;  // B per element, W / m^2 per channel
    // H per element, W / m^2 per channel: the light that arrives, before it is reflected
    // (B = E + rho H). The camera pass shows textures as rho(uv) H / pi.
    std::vector<glm::vec3> irradiance;
    // Of H, the light that arrived by way of mirrors or glass, W / m^2 per channel: the progressive
    // solve's with mirrors or glass in the scene (the camera pass's sampled modes read it apart);
    // empty otherwise.
    std::vector<glm::vec3> causticIrradiance;
    EnergyBalance energy;
    std::string stopped;          // tolerance, max-shots, time-limit, interrupted, bounces, max-iterations
    double unshotFraction = 0.0;  // progressive: unshot / emitted power when it stopped
    SolveTallies tallies;
    std::uint64_t iterations = 0;  // matrix solvers: sweeps (shots for progressive)
    double residual = -1.0;        // matrix solvers: the residual; -1: none
    int refinementPasses = 0;
    std::size_t clusters = 0;  // progressive: the clusters of patches that shot (mesh/patch_clusters.h)
    std::size_t pooled = 0;    // progressive: elements whose shot light is more their cluster's than their own (cluster_receivers.h)
    double sumSeconds = 0.0;  // several processes: the time spent summing their shots' counts
    double rayPowerScale = 1.0;  // progressive: the largest power per ray over emitted / --rays
    // progressive: the noise expected in the elements' radiosity, relative (solver/ray_hit_checks.h); -1: none
    double expectedNoise = -1.0;
    std::vector<std::pair<std::string, double>> parameters;  // the report's method_parameters
    std::string summary;  // a few words for the last line: "1234 shots, unshot 9.9e-04"
};

// How the caller watches and steers a solve.
struct SolveControl {
    std::function<void(const SolveProgress&)> progress;  // progressive solves, after every batch
    std::function<bool()> interrupted;                   // asked between batches and passes
    std::function<void(const std::string&)> note;        // a line for the user (refinement passes)
    std::function<void(const std::string&)> warn;        // a warning for stderr and the report
    // The processes sharing the solve (parallel/process_group.h); one when null. Every process
    // runs the strategy and ends with the same Solution; only the root writes checkpoints.
    // `interrupted` must then answer the same on every process.
    const ProcessGroup* group = nullptr;
    // Where solver states are saved and read back (--checkpoint, --resume), given by the command
    // (io/checkpoint.h writes the files); without them a strategy refuses those options.
    std::function<void(const std::string& path, const SolverState& state, std::uint64_t fingerprint)> saveState;
    std::function<SolverState(const std::string& path, std::uint64_t fingerprint)> loadState;
};

class SolveStrategy {
public:
    virtual ~SolveStrategy() = default;
    // Every option this strategy reads, for the check that refuses the others.
    virtual std::vector<OptionSpec> options() const = 0;
    // Before the work, on the prepared scene: warnings the sampling earns, and refusals.
    virtual void check(const PreparedScene& scene, const SolveControl& control) const { (void)scene, (void)control; }
    virtual Solution solve(const PreparedScene& scene, const SolveControl& control) = 0;
    // Whether it asks control.interrupted and stops with a whole solution when told to (the
    // command then catches SIGINT and SIGTERM instead of ending at once).
    virtual bool stopsWhenInterrupted() const { return false; }
};

// What the strategies are built from: the method, the solver, the options the user gave and
// the seed.
struct SolveChoice {
    std::string method = "shoot";
    std::string solver = "progressive";
    OptionValues values;
    std::uint32_t seed = 1;
};

struct SolveStrategyEntry {
    std::string name;
    std::string description;
    std::string chosenBy;             // when the registry picks it, in the user's words (for messages)
    std::vector<OptionSpec> options;  // its own; the matrix strategy adds its estimator's and solver's
    bool (*takes)(const std::string& method, const std::string& solver);
    // Throws InputError for options that cannot work together (before any work).
    std::unique_ptr<SolveStrategy> (*create)(const SolveChoice& choice);
};

const std::vector<SolveStrategyEntry>& solveStrategies();
// The entry that takes (method, solver); InputError when none does.
const SolveStrategyEntry& solveStrategyFor(const std::string& method, const std::string& solver);
std::unique_ptr<SolveStrategy> makeSolveStrategy(const SolveChoice& choice);

// Each strategy's entry, defined in its own file.
SolveStrategyEntry deviceProgressiveStrategy();
SolveStrategyEntry matrixStrategy();

}  // namespace rad
