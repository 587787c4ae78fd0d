// The device-progressive strategy: progressive refinement resident on the device
// (progressive_solver.h), patches shooting rays and elements receiving, with two levels
// (--element-size), adaptive refinement (refinement.h), checkpoints and resume, and the ray-hit
// check on the result. Takes --method shoot --solver progressive, the default.

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <limits>
#include <optional>

#include "prepared/prepared_scene.h"
#include "solver/progressive_options.h"
#include "solver/progressive_solver.h"
#include "solver/ray_hit_checks.h"
#include "solver/refinement.h"
#include "solver/solve_strategy.h"
#include "util/error.h"
#include "util/fnv.h"

namespace rad {
namespace {

ProgressiveOptions progressiveOptions(const OptionValues& v, std::uint32_t seed) {
    ProgressiveOptions options;
    options.rays = v.count64(kRaysOption);
    options.minRays = v.count32(kMinRaysOption);
    options.tolerance = v.number(kToleranceOption);
    options.maxShots = v.count64(kMaxShotsOption);
    options.timeLimit = v.number(kTimeLimitOption);
    options.seed = seed;
    if (v.flag(kNoOvershootOption)) options.amplificationThreshold = std::numeric_limits<double>::infinity();
    options.clusters = !v.flag(kNoClustersOption);
    options.pooling = !v.flag(kNoPoolingOption);
    return options;
}

// Identifies the problem a checkpoint belongs to: the scene's bytes, the light the command line
// adds (a sky), the mesh, and every option that steers which shots are taken (stopping criteria
// may differ on resume).
std::uint64_t problemFingerprint(const Scene& scene, const Mesh& mesh, const ProgressiveOptions& o) {
    Fnv1a hash;
    for (const std::string& file : scene.files.empty() ? std::vector<std::string>{scene.path} : scene.files) {
        std::ifstream in(file, std::ios::binary);
        hash.add(std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>()));
    }
    // Only a sky that is there, so checkpoints of scenes without one keep their fingerprints.
    if (scene.sky != glm::vec3(0.0f))
        hash.add(static_cast<double>(scene.sky.x))
            .add(static_cast<double>(scene.sky.y))
            .add(static_cast<double>(scene.sky.z));
    if (scene.environment) hash.add(environmentFingerprint(*scene.environment));
    // Only when it changes the shots, so other checkpoints keep their fingerprints.
    if (!std::isfinite(o.amplificationThreshold)) hash.add(std::string("no-overshoot"));
    if (!o.clusters) hash.add(std::string("no-clusters"));
    return hash.add(mesh.patchSize)
        .add(static_cast<std::uint64_t>(mesh.patches.size()))
        .add(o.rays)
        .add(o.minRays)
        .add(o.seed)
        .add(o.maxShootersPerBatch)
        .add(o.batchPowerRatio)
        .value();
}

class DeviceProgressive : public SolveStrategy {
public:
    explicit DeviceProgressive(const SolveChoice& choice) : values_(choice.values), seed_(choice.seed) {}

    std::vector<OptionSpec> options() const override { return ownOptions(); }
    bool stopsWhenInterrupted() const override { return true; }

    static std::vector<OptionSpec> ownOptions() {
        return {kRaysOption,           kNoOvershootOption, kMinRaysOption,     kNoClustersOption, kNoPoolingOption,
                kToleranceOption,
                kMaxShotsOption,       kTimeLimitOption,   kCheckpointOption,  kCheckpointEveryOption,
                kResumeOption,         kElementSizeOption, kAdaptiveOption,    kRefineThresholdOption,
                kMinElementSizeOption, kMaxElementsOption, kRefinePassesOption};
    }

    Solution solve(const PreparedScene& scene, const SolveControl& control) override {
        Solution s;
        s.elements = ElementMesh::uniform(scene.mesh(), values_.number(kElementSizeOption));
        if (values_.flag(kAdaptiveOption)) s.refinementPasses = refine(scene, s.elements, control);
        const ProgressiveOptions options = progressiveOptions(values_, seed_);
        const std::uint64_t fingerprint = problemFingerprint(scene.scene(), scene.mesh(), options);
        std::optional<SolverState> resumed;
        const std::string resume = values_.text(kResumeOption), checkpoint = values_.text(kCheckpointOption);
        if ((!resume.empty() && !control.loadState) || (!checkpoint.empty() && !control.saveState))
            throw InputError("--checkpoint and --resume need a place to keep solver states, which this caller does "
                             "not give");
        if (!resume.empty()) resumed = control.loadState(resume, fingerprint);
        SolveHooks hooks;
        hooks.progress = control.progress;
        hooks.interrupted = control.interrupted;
        hooks.group = control.group;
        if (!checkpoint.empty() && (!control.group || control.group->root())) {
            hooks.checkpointEvery = values_.number(kCheckpointEveryOption);
            hooks.checkpoint = [checkpoint, fingerprint, save = control.saveState](const SolverState& state) {
                save(checkpoint, state, fingerprint);
            };
        }
        const ProgressiveResult result =
            ProgressiveSolver(scene, s.elements).solve(options, hooks, resumed ? &*resumed : nullptr);
        s.radiosity = result.radiosity;
        s.irradiance.resize(result.incident.size());
        for (std::size_t e = 0; e < result.incident.size(); ++e) {
            const float area = s.elements.elements()[e].area;
            s.irradiance[e] = area > 0.0f ? result.incident[e] / area : glm::vec3(0.0f);
        }
        s.causticIrradiance.resize(result.caustic.size());
        for (std::size_t e = 0; e < result.caustic.size(); ++e) {
            const float area = s.elements.elements()[e].area;
            s.causticIrradiance[e] = area > 0.0f ? result.caustic[e] / area : glm::vec3(0.0f);
        }
        s.energy = result.energy;
        s.stopped = stopReasonName(result.stopped);
        s.unshotFraction = result.unshotFraction;
        s.tallies = result.tallies;
        s.clusters = result.clusters;
        s.pooled = result.pooled;
        s.sumSeconds = result.sumSeconds;
        s.rayPowerScale = result.rayPowerScale;
        s.expectedNoise = relativeNoise(result.receivers);
        if (control.warn)
            for (const std::string& w :
                 rayHitWarnings(result.receivers, s.elements.elements().size(), scene.patches().size(), options.rays))
                control.warn(w);
        char summary[96];
        std::snprintf(summary, sizeof summary, "%llu shots, unshot %.2e", static_cast<unsigned long long>(s.tallies.shots),
                      s.unshotFraction);
        s.summary = summary;
        return s;
    }

private:
    // Adaptive refinement: passes by direct light, then one by a provisional solve with a
    // quarter of the rays, to unshot 1e-2. Returns the passes that ran.
    int refine(const PreparedScene& scene, ElementMesh& elements, const SolveControl& control) const {
        ProgressiveOptions provisional = progressiveOptions(values_, seed_);
        provisional.directLightRays = provisional.rays;
        provisional.rays = std::max<std::uint64_t>(1, provisional.rays / 4);
        provisional.tolerance = std::max(provisional.tolerance, 1e-2);
        provisional.maxShots = 0;
        provisional.timeLimit = 0.0;
        AdaptiveOptions options;
        options.marks.threshold = values_.number(kRefineThresholdOption);
        options.marks.seed = seed_;
        const double minEdge = values_.number(kMinElementSizeOption);
        options.minEdge = minEdge > 0.0 ? minEdge : scene.mesh().patchSize / 16.0;
        options.maxElements = values_.count64(kMaxElementsOption);
        options.passes = static_cast<int>(values_.count32(kRefinePassesOption));
        options.finalRays = values_.count64(kRaysOption);
        options.group = control.group;
        int number = 0;
        const auto passes = refineAdaptively(
            scene, elements, provisional, options, control.interrupted, [&](const RefinementPass& pass) {
                if (!control.note) return;
                char line[256];
                std::snprintf(line, sizeof line,
                              "refinement pass %d (%s): %zu of %zu elements marked, %zu "
                              "left whole for want of rays; now %zu elements (%.2f s)",
                              ++number, pass.bySolution ? "provisional solve" : "direct light", pass.marked,
                              pass.examined, pass.tooFewRays, pass.after, pass.seconds);
                control.note(line);
            });
        return static_cast<int>(passes.size());
    }

    OptionValues values_;
    std::uint32_t seed_;
};

}  // namespace

SolveStrategyEntry deviceProgressiveStrategy() {
    return {"device-progressive",
            "progressive refinement resident on the device: patches shoot rays, elements receive",
            "--method shoot --solver progressive",
            DeviceProgressive::ownOptions(),
            [](const std::string& method, const std::string& solver) {
                return method == "shoot" && solver == "progressive";
            },
            [](const SolveChoice& choice) -> std::unique_ptr<SolveStrategy> {
                const OptionValues& v = choice.values;
                if (v.number(kToleranceOption) <= 0.0 && v.count64(kMaxShotsOption) == 0 &&
                    v.number(kTimeLimitOption) <= 0.0)
                    throw InputError("--tolerance 0 never stops by itself: give --max-shots or --time-limit too");
                if (v.flag(kAdaptiveOption) && (!v.text(kCheckpointOption).empty() || !v.text(kResumeOption).empty()))
                    throw InputError("--checkpoint and --resume do not work with --adaptive yet");
                return std::make_unique<DeviceProgressive>(choice);
            }};
}

}  // namespace rad
