#pragma once
// Progressive-refinement radiosity in power form, resident on the device (docs/architecture.md,
// "Conventions"): each batch shoots the patches with the most unshot power, every receiver j
// takes rho_j F_ij dPhi_i per channel into its radiosity and its unshot power, and the
// shooters' unshot power goes to zero. The host reads back only a reduction of the unshot power
// per batch. Light from emitters that are not shot (light/emitter.h) arrives at the elements
// before the first batch; what they reflect of it is shot like the rest.
//
// Rays per shot follow the shooter's power: N_i = clamp(N * dPhi_i / Phi_emitted, minRays,
// 2^31), dPhi summed over channels, so every ray carries about the same power (Phi_emitted /
// N) and the noise each shot adds is in proportion to the power it moves, which minimises the
// total variance for a given number of rays. A shooter keeps one scrambled Sobol sequence over
// all its shots, so repeated shots stay stratified.
//
// Under several processes (SolveHooks::group) the batch's shooters are divided by their rays
// (divideByCost), each process delivers its share's power into its own 64-bit fixed-point
// counts, and one sum over the processes per batch (elements x 3 x 8 bytes) gives every process
// the counts one process would have: integer addition does not depend on who added what.

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "formfactor/counter_layout.h"
#include "mesh/elements.h"
#include "parallel/process_group.h"
#include "prepared/prepared_scene.h"
#include "solver/amplification.h"
#include "solver/energy_balance.h"
#include "solver/ray_hit_checks.h"
#include "solver/solver_state.h"

namespace rad {

struct ProgressiveOptions {
    std::uint64_t rays = 16'000'000;    // rays a shooter holding all the emitted power would cast
    std::uint32_t minRays = 128;        // rays of the weakest shots
    double tolerance = 1e-3;            // stop when unshot / emitted power falls below this
    std::uint64_t maxShots = 0;         // 0: no limit
    double timeLimit = 0.0;             // seconds; 0: no limit
    std::uint32_t seed = 1;
    std::uint32_t maxShootersPerBatch = 1024;  // clusters of patches (mesh/patch_clusters.h)
    // Small patches shoot in clusters (mesh/patch_clusters.h); false: each on its own (for
    // comparisons).
    bool clusters = true;
    // The shots' light is pooled over a cluster's elements as far as their hits agree
    // (solver/cluster_receivers.h); false: each keeps its own (for comparisons).
    bool pooling = true;
    // The rays the sky's or environment map's direct light is sampled by follow (in proportion
    // to the default, solver/direct_light.h); 0: `rays`. A provisional solve with fewer rays keeps
    // the final solve's, so that what it tells apart is not that light's noise.
    std::uint64_t directLightRays = 0;
    double batchPowerRatio = 0.5;       // a batch shoots candidates with at least this share of the strongest
    // Above this gain of the scene's light, rays carry more power and shooters overshoot
    // (solver/amplification.h); infinity: never (for comparisons).
    double amplificationThreshold = Amplification::kThreshold;
    // How the shots add into the delivered-power counters; unset: the device's choice
    // (CounterLayout::forDevice). The result is the same bits for any layout: for benchmarks
    // and tests.
    std::optional<CounterLayout> counters;
};

enum class StopReason { Tolerance, MaxShots, TimeLimit, Interrupted };
const char* stopReasonName(StopReason reason);

struct SolveProgress {
    std::uint64_t shots = 0;
    std::uint64_t rays = 0;
    double unshotFraction = 1.0;
    double seconds = 0.0;
};

struct ProgressiveResult {
    std::vector<glm::vec3> radiosity;   // B per element, W/m^2 per channel
    std::vector<glm::vec3> incident;    // power that arrived at each element, W per channel
    // Of that, the power that arrived by way of mirrors or glass (kernels/shoot.cl's
    // walk_specular, specular_walk.h), W per channel; empty where the scene has neither.
    std::vector<glm::vec3> caustic;
    SolveTallies tallies;
    StopReason stopped = StopReason::Tolerance;
    double unshotFraction = 1.0;
    EnergyBalance energy;
    double seconds = 0.0;
    std::map<std::string, double> kernelSeconds;  // device time per kernel (needs a profiling context)
    double sumSeconds = 0.0;  // several processes: summing the batches' counts (read, sum, write back)
    // The largest power per ray, over emitted / rays, that a shot used (solver/amplification.h:
    // above 1 where the scene amplifies its light more than Amplification::kThreshold).
    double rayPowerScale = 1.0;
    CounterLayout counters;  // how the shots added into the delivered-power counters
    std::size_t clusters = 0;  // clusters of patches that shot (the patch count where none is small)
    // Elements whose shot light is more their cluster's than their own (solver/cluster_receivers.h).
    std::size_t pooled = 0;
    // Per element that reflects light, the noise its value is expected to carry: what
    // solver/ray_hit_checks.h reads.
    std::vector<ReceiverNoise> receivers;
};

// What the caller can watch and steer while a solve runs.
struct SolveHooks {
    std::function<void(const SolveProgress&)> progress;  // after every batch
    std::function<bool()> interrupted;                   // asked before every batch
    // Called at a batch boundary once checkpointEvery seconds have passed since the last call,
    // and once more when the solve stops, with the state to save.
    std::function<void(const SolverState&)> checkpoint;
    double checkpointEvery = 0.0;
    // The processes that share each batch's shots (parallel/process_group.h); one when null.
    // Each shoots its share of a batch's shooters and they sum what the receivers took, so
    // every process holds bitwise the state of one process. `interrupted` must then give the
    // same answer on every process (anyProcess), and the time limit is agreed the same way.
    const ProcessGroup* group = nullptr;
};

class ProgressiveSolver {
public:
    // Patches shoot; the elements of `elements` receive (ElementMesh::uniform(mesh, 0): one
    // element per patch).
    ProgressiveSolver(const PreparedScene& scene, const ElementMesh& elements);

    // Starts from the emitters, or continues from `resume` (a state of this scene, mesh and
    // options). Throws InputError when nothing in the scene emits, or when `resume` does not fit
    // the mesh.
    ProgressiveResult solve(const ProgressiveOptions& options, const SolveHooks& hooks = {},
                            const SolverState* resume = nullptr);

private:
    const PreparedScene& scene_;
    const ElementMesh& elements_;
};

}  // namespace rad
