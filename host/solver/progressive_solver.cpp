#include "solver/progressive_solver.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "device/kernel_arguments.h"
#include "formfactor/launch_plan.h"
#include "formfactor/ray_shooter.h"
#include "device/device_elements.h"
#include "mesh/patch_clusters.h"
#include "prepared/patch_system.h"
#include "shared_math.h"
#include "solver/amplification.h"
#include "solver/cluster_receivers.h"
#include "solver/direct_light.h"
#include "solver/shooter_selection.h"
#include "util/error.h"
#include "util/fnv.h"
#include "util/sample_streams.h"
#include "util/stopwatch.h"

namespace rad {
namespace {

// Gather work items: enough to keep a GPU busy, few enough that their partials are a small read.
constexpr std::uint32_t kMaxGatherItems = 4096;

// Columns of one set of delivered-power counters: the elements, what escaped, what black backs
// took, and with specular transport the elements once more, for what came by specular paths
// (kernels/shoot.cl).
std::uint32_t powerColumns(std::uint32_t elementCount, bool caustics) {
    return elementCount + 2 + (caustics ? elementCount : 0);
}

// Words of one set: columns x 3 channels x 2 words.
std::size_t powerSetWords(std::uint32_t columns) {
    return std::size_t{columns} * 6;
}

// The device side of one solve: per-patch state and the batch's arrays.
class DeviceState {
public:
    // Per patch: reflectance and unshot power; per element: incident power (w: the element's
    // own unshot power, summed over channels, that decides where its patch's rays start).
    // caustic: per element, the incident power that came by specular paths (empty: the scene has
    // no mirrors or glass, and the counters no columns for it).
    // clusters: which patches shoot together (mesh/patch_clusters.h); maxShooters: the most
    // shooters (patches) of one batch.
    DeviceState(ComputeContext& compute, const DeviceElements& elements, const std::vector<rad_float4>& reflectance,
                const std::vector<float>& area, const std::vector<rad_float4>& incident,
                const std::vector<rad_float4>& unshot, const std::vector<rad_float4>& caustic,
                const PatchClusters& clusters, std::uint32_t maxShooters, std::uint32_t counterSets)
        : patchCount_(static_cast<std::uint32_t>(reflectance.size())),
          elementCount_(static_cast<std::uint32_t>(incident.size())),
          gatherItems_(std::clamp<std::uint32_t>(static_cast<std::uint32_t>(clusters.count()) / 4, 1, kMaxGatherItems)),
          sets_(counterSets),
          columns_(powerColumns(elementCount_, !caustic.empty())) {
        const std::string patches = " (" + std::to_string(patchCount_) + " patches)";
        reflectance_ = DeviceArray<rad_float4>::upload(compute, reflectance, "patch reflectances" + patches);
        area_ = DeviceArray<float>::upload(compute, area, "patch areas" + patches);
        unshot_ = DeviceArray<rad_float4>::upload(compute, unshot, "unshot power" + patches, DeviceAccess::readWrite);
        incident_ = DeviceArray<rad_float4>::upload(compute, incident, "incident power", DeviceAccess::readWrite);
        caustic_ = DeviceArray<rad_float4>::upload(compute, caustic, "caustic power", DeviceAccess::readWrite);
        power_ = DeviceArray<rad_uint>::upload(compute, std::vector<rad_uint>(powerWords(), 0u), "delivered power",
                                               DeviceAccess::readWrite);
        elementCdf_ = DeviceArray<rad_uint>::allocate(compute, elementCount_, "element shares");
        touched_ = DeviceArray<rad_uint>::upload(
            compute, std::vector<rad_uint>((elementCount_ >> RAD_TOUCHED_SHIFT) + 1, 0u), "elements the shots reached",
            DeviceAccess::readWrite);
        shooters_ = DeviceArray<Shooter>::allocate(compute, std::max(1u, maxShooters), "shooters", DeviceAccess::read);
        partials_ = DeviceArray<UnshotPartial>::allocate(compute, gatherItems_, "unshot partials", DeviceAccess::write);
        lost_ = DeviceArray<rad_float4>::allocate(compute, 2, "lost power", DeviceAccess::write);
        clusterStart_ = DeviceArray<rad_uint>::upload(compute, clusters.start(), "patch clusters");
        clusterMembers_ = DeviceArray<rad_uint>::upload(compute, clusters.members(), "patch clusters' patches");
        if (!clusters.isIdentity()) {
            memberPatches_ = DeviceArray<rad_uint>::allocate(compute, std::max(1u, maxShooters), "shooting patches",
                                                             DeviceAccess::read);
            memberPowers_ = DeviceArray<rad_float4>::allocate(compute, std::max(1u, maxShooters),
                                                              "shooting patches' power", DeviceAccess::write);
            members_ = makeKernel<MemberPowersArgs>(compute, "progressive.cl", "member_powers");
            membersArgs_.patches = memberPatches_;
            membersArgs_.reflectance = reflectance_;
            membersArgs_.unshot = unshot_;
            membersArgs_.patchArea = area_;
            membersArgs_.powers = memberPowers_;
        }
        prepare_ = makeKernel<PrepareShootersArgs>(compute, "progressive.cl", "prepare_shooters");
        take_ = makeKernel<TakeShotsArgs>(compute, "progressive.cl", "take_shots");
        gather_ = makeKernel<GatherArgs>(compute, "progressive.cl", "gather");
        prepareArgs_.shooters = shooters_;
        prepareArgs_.elementStart = elements.elementStart;
        prepareArgs_.incident = incident_;
        prepareArgs_.frames = elements.frames;
        prepareArgs_.ends = elementCdf_;
        takeArgs_.shooters = shooters_;
        takeArgs_.unshot = unshot_;
        gatherArgs_.power = power_;
        gatherArgs_.reflectance = reflectance_;
        gatherArgs_.incident = incident_;
        gatherArgs_.unshot = unshot_;
        gatherArgs_.elementStart = elements.elementStart;
        gatherArgs_.patchCount = patchCount_;
        gatherArgs_.elementCount = elementCount_;
        gatherArgs_.workItems = gatherItems_;
        gatherArgs_.partials = partials_;
        gatherArgs_.lost = lost_;
        gatherArgs_.patchArea = area_;
        gatherArgs_.sets = sets_;
        gatherArgs_.columns = columns_;
        gatherArgs_.caustic = caustic_;
        gatherArgs_.clusterStart = clusterStart_;
        gatherArgs_.clusterMembers = clusterMembers_;
        gatherArgs_.clusterCount = static_cast<std::uint32_t>(clusters.count());
        gatherArgs_.touched = touched_;
    }

    DeviceArray<rad_uint>& power() { return power_; }
    std::uint32_t columns() const { return columns_; }
    const DeviceArray<Shooter>& shooters() const { return shooters_; }
    const DeviceArray<rad_uint>& elementCdf() const { return elementCdf_; }
    DeviceArray<rad_uint>& touched() { return touched_; }

    // Not blocking: `shooters` must stay alive until the batch's gather() has returned.
    void writeShooters(const std::vector<Shooter>& shooters) { shooters_.enqueueWrite(shooters); }

    // Before the batch's shots: where on its patch each shooter's rays start.
    void prepareShooters(std::uint32_t count) {
        prepareArgs_.shooterCount = count;
        prepare_.launch(prepareArgs_, count);
    }

    void takeShots(std::uint32_t count) {
        takeArgs_.shooterCount = count;
        take_.launch(takeArgs_, count);
    }

    // Delivers the batch's power and reduces the unshot power; returns the partials and adds
    // what left the scene and what black backs took to `escaped` and `backs`. `overshoot`: the
    // irradiance per channel the unshot power is expected still to bring (0: none).
    std::vector<UnshotPartial> gather(float quantum, const glm::vec3& overshoot, glm::dvec3& escaped,
                                      glm::dvec3& backs) {
        gatherArgs_.quantum = quantum;
        gatherArgs_.overshoot = {{overshoot.x, overshoot.y, overshoot.z, 0.0f}};
        membersArgs_.overshoot = gatherArgs_.overshoot;
        gather_.launch(gatherArgs_, gatherItems_);
        touched_.fill(0u);  // the gather zeroed the counters it read; the others were 0
        std::vector<UnshotPartial> partials(gatherItems_);
        partials_.enqueueRead(partials);
        const std::vector<rad_float4> lost = lost_.read(2);
        for (int c = 0; c < 3; ++c) {
            escaped[c] += lost[0].s[c];
            backs[c] += lost[1].s[c];
        }
        return partials;
    }

    // Under several processes each delivered only its own shooters' power: every process's
    // counts are summed (exactly: integers modulo 2^64, as the device adds them) and put back,
    // the counter sets added first into the first set.
    void sumPowerOver(const ProcessGroup& group) {
        powerWords_ = power_.read();
        const std::size_t perSet = powerWords_.size() / sets_;
        std::vector<std::uint64_t> counts(perSet / 2, 0);
        for (std::uint32_t k = 0; k < sets_; ++k)
            for (std::size_t i = 0; i < counts.size(); ++i)
                counts[i] += powerWords_[k * perSet + 2 * i] | std::uint64_t{powerWords_[k * perSet + 2 * i + 1]} << 32;
        group.sum(counts);
        std::fill(powerWords_.begin() + static_cast<std::ptrdiff_t>(perSet), powerWords_.end(), 0u);
        for (std::size_t i = 0; i < counts.size(); ++i) {
            powerWords_[2 * i] = static_cast<rad_uint>(counts[i]);
            powerWords_[2 * i + 1] = static_cast<rad_uint>(counts[i] >> 32);
        }
        power_.enqueueWrite(powerWords_);  // powerWords_ outlives the batch's blocking read
        touched_.fill(1u);                 // other processes' shots reached elements this one's did not
    }

    // The power to shoot of each of `patches` (at most maxShooters), as the last gather measured it.
    std::vector<rad_float4> memberPowers(const std::vector<rad_uint>& patches) {
        if (patches.empty()) return {};
        memberPatches_.enqueueWrite(patches);
        membersArgs_.patchCount = static_cast<std::uint32_t>(patches.size());
        members_.launch(membersArgs_, patches.size());
        return memberPowers_.read(patches.size());
    }

    std::vector<rad_float4> readIncident() { return incident_.read(); }
    std::vector<rad_float4> readUnshot() { return unshot_.read(); }
    std::vector<rad_float4> readCaustic() {
        if (columns_ == elementCount_ + 2) return {};
        return caustic_.read();
    }

private:
    std::size_t powerWords() const { return powerSetWords(columns_) * sets_; }

    std::uint32_t patchCount_, elementCount_;
    std::uint32_t gatherItems_;
    std::uint32_t sets_;     // sets of delivered-power counters (CounterLayout)
    std::uint32_t columns_;  // columns of each set (powerColumns)
    DeviceArray<rad_float4> reflectance_, unshot_, incident_, caustic_, lost_, memberPowers_;
    DeviceArray<float> area_;
    DeviceArray<rad_uint> power_, elementCdf_, clusterStart_, clusterMembers_, memberPatches_, touched_;
    DeviceArray<Shooter> shooters_;
    DeviceArray<UnshotPartial> partials_;
    std::vector<rad_uint> powerWords_;  // the summed counts on their way back to the device
    DeviceKernel<PrepareShootersArgs> prepare_;
    DeviceKernel<TakeShotsArgs> take_;
    DeviceKernel<GatherArgs> gather_;
    DeviceKernel<MemberPowersArgs> members_;
    PrepareShootersArgs prepareArgs_;
    TakeShotsArgs takeArgs_;
    GatherArgs gatherArgs_;
    MemberPowersArgs membersArgs_;
};

// Keeps one Sobol sequence per shooter over all its shots; past 2^32 samples a new scramble
// starts a fresh sequence.
class SampleCounters {
public:
    SampleCounters(std::vector<std::uint64_t> used, std::uint32_t seed)
        : used_(std::move(used)), stream_(rad_hash2(seed, kShooterRaysStream)) {}
    const std::vector<std::uint64_t>& used() const { return used_; }

    RayRequest request(std::uint32_t patch, std::uint32_t rays, std::uint32_t row) {
        std::uint64_t& used = used_[patch];
        if ((used & 0xFFFFFFFFull) + rays > (std::uint64_t{1} << 32)) used = ((used >> 32) + 1) << 32;
        RayRequest r;
        r.firstTriangle = patch;
        r.triangleCount = 1;
        r.rays = rays;
        r.firstSample = static_cast<std::uint32_t>(used & 0xFFFFFFFFull);
        r.scramble = rad_hash2(rad_hash2(stream_, patch), static_cast<std::uint32_t>(used >> 32));
        r.row = row;
        used += rays;
        return r;
    }

private:
    std::vector<std::uint64_t> used_;
    std::uint32_t stream_;
};

// Sum of rho_j A_j over the patches, per channel: how much area reflects how much.
glm::dvec3 reflectedArea(const std::vector<glm::vec3>& reflectance, const PatchSystem& system) {
    glm::dvec3 sum(0.0);
    for (std::size_t p = 0; p < system.size(); ++p)
        sum += glm::dvec3(reflectance[p]) * static_cast<double>(system.area[p]);
    return sum;
}

glm::dvec3 maxReflectance(const std::vector<glm::vec3>& reflectance) {
    glm::dvec3 most(0.0);
    for (const glm::vec3& rho : reflectance) most = glm::max(most, glm::dvec3(rho));
    return most;
}

// The diffuse reflectance the solve uses per patch: the scene's, or where the shots carry light
// through mirrors and glass (kernels/shoot.cl), 0 on those, which reflect nothing diffusely.
std::vector<glm::vec3> solveReflectance(const PreparedScene& scene) {
    if (!scene.device().specularFaces()) return scene.patches().reflectance;
    return reflectanceBesideSpecular(scene.patches(), scene.scene(), scene.mesh());
}

double unshotTotal(const std::vector<UnshotPartial>& partials) {
    double total = 0.0;
    for (const UnshotPartial& p : partials) total += p.unshotSum;
    return total;
}

}  // namespace

const char* stopReasonName(StopReason reason) {
    switch (reason) {
        case StopReason::Tolerance: return "tolerance";
        case StopReason::MaxShots: return "max-shots";
        case StopReason::TimeLimit: return "time-limit";
        case StopReason::Interrupted: return "interrupted";
    }
    return "unknown";
}

ProgressiveSolver::ProgressiveSolver(const PreparedScene& scene, const ElementMesh& elements)
    : scene_(scene), elements_(elements) {}

namespace {

// The host's copy of the solver's state, in device units, before it goes to the device.
struct InitialState {
    double scale = 1.0;      // device units per watt: puts the strongest emitted channel in [1, 2)
    double emitted = 0.0;    // power to shoot at the start in device units, summed over channels
    std::vector<rad_float4> reflectance, unshot, incident;
    std::vector<rad_float4> caustic;  // per element where light goes through mirrors and glass, else empty
};

// Where a solve starts from nothing: each patch's emitted power as unshot power, and each
// element's share of it; the direct light of emitters the solver does not shoot (light/emitter.h)
// arrives at the elements before the first shot, and what they reflect of it is unshot.
InitialState initialState(const PreparedScene& scene, const std::vector<glm::vec3>& reflectance,
                          const ElementMesh& elements, const DirectLight& direct, ProgressiveResult& result) {
    const PatchSystem& system = scene.patches();
    const std::size_t patchCount = system.size(), elementCount = elements.elements().size();
    const std::vector<glm::vec3> exitance = system.exitance();
    for (std::size_t p = 0; p < patchCount; ++p)
        result.energy.emitted += glm::dvec3(exitance[p]) * static_cast<double>(system.area[p]);
    if (!direct.empty()) result.energy.emitted += direct.total();
    const double strongest = std::max({result.energy.emitted.x, result.energy.emitted.y, result.energy.emitted.z});
    if (!(strongest > 0.0)) throw InputError("nothing in the scene emits light: there is nothing to solve");
    InitialState state;
    // The device works in units that put the strongest channel's emitted power in [1, 2): a
    // power of two, so scaling is exact, and single precision is spent on the light's own range
    // however bright or faint the scene is in watts.
    int exponent = 0;
    std::frexp(strongest, &exponent);
    state.scale = std::ldexp(1.0, 1 - exponent);
    state.reflectance.resize(patchCount);
    state.unshot.resize(patchCount);
    state.incident.assign(elementCount, rad_float4{{0, 0, 0, 0}});
    if (scene.device().specularFaces()) state.caustic.assign(elementCount, rad_float4{{0, 0, 0, 0}});
    for (std::size_t p = 0; p < patchCount; ++p) {
        const glm::dvec3 power = glm::dvec3(exitance[p]) * static_cast<double>(system.area[p]) * state.scale;
        state.reflectance[p] = float4Of(reflectance[p]);
        state.unshot[p] = float4Of(glm::vec3(power));
        state.emitted += static_cast<double>(state.unshot[p].s[0]) + state.unshot[p].s[1] + state.unshot[p].s[2];
    }
    // What each element emits is its share of its patch's, by area (scale^2 of the patch's).
    for (std::size_t e = 0; e < elementCount; ++e) {
        const Element& element = elements.elements()[e];
        const rad_float4& power = state.unshot[element.patch];
        state.incident[e].s[3] = (power.s[0] + power.s[1] + power.s[2]) * element.frame.scale * element.frame.scale;
    }
    if (!direct.empty()) {
        for (std::size_t e = 0; e < elementCount; ++e) {
            const std::uint32_t p = elements.elements()[e].patch;
            const glm::vec3 arrived(direct.arrived[e] * state.scale);
            const glm::vec3 reflected = reflectance[p] * arrived;
            for (int c = 0; c < 3; ++c) {
                state.incident[e].s[c] += arrived[c];
                state.unshot[p].s[c] += reflected[c];
            }
            state.incident[e].s[3] += reflected.x + reflected.y + reflected.z;
        }
        // The sky's and the punctual lights' light through a window or off a mirror: part of the
        // light that came by way of mirrors and glass, which the camera pass reads apart.
        if (!state.caustic.empty() && !direct.arrivedBySpecular.empty())
            for (std::size_t e = 0; e < elementCount; ++e) {
                const glm::vec3 arrived(direct.arrivedBySpecular[e] * state.scale);
                for (int c = 0; c < 3; ++c) state.caustic[e].s[c] += arrived[c];
            }
        // Rays are shared out by the power there is to shoot: what the patches emit and what
        // they reflect of the direct light, not the direct light that escaped or was absorbed.
        state.emitted = 0.0;
        for (const rad_float4& power : state.unshot)
            state.emitted += static_cast<double>(power.s[0]) + power.s[1] + power.s[2];
    }
    return state;
}

// Continues from a saved state instead: its per-patch and per-element state and its tallies.
void resumeFrom(const SolverState& saved, InitialState& state, std::vector<std::uint64_t>& samplesUsed,
                SolverState& progress) {
    const std::size_t patchCount = state.unshot.size(), elementCount = state.incident.size();
    if (saved.incident.size() != elementCount || saved.unshot.size() != patchCount || saved.samplesUsed.size() != patchCount)
        throw InputError("the saved state holds " + std::to_string(saved.unshot.size()) + " patches and " +
                         std::to_string(saved.incident.size()) + " elements; this mesh has " + std::to_string(patchCount) +
                         " and " + std::to_string(elementCount));
    for (std::size_t p = 0; p < patchCount; ++p)
        for (int c = 0; c < 4; ++c) state.unshot[p].s[c] = saved.unshot[p][c];
    for (std::size_t e = 0; e < elementCount; ++e)
        for (int c = 0; c < 4; ++c) state.incident[e].s[c] = saved.incident[e][c];
    if (saved.caustic.size() != state.caustic.size())
        throw InputError("the saved state holds " + std::to_string(saved.caustic.size()) +
                         " elements' light through mirrors and glass; this scene needs " +
                         std::to_string(state.caustic.size()));
    for (std::size_t e = 0; e < state.caustic.size(); ++e)
        for (int c = 0; c < 4; ++c) state.caustic[e].s[c] = saved.caustic[e][c];
    samplesUsed = saved.samplesUsed;
    progress.escaped = saved.escaped;
    progress.shot = saved.shot;
    progress.absorbedByBacks = saved.absorbedByBacks;
    progress.tallies = saved.tallies;
    progress.seconds = saved.seconds;
}

// Several processes hold the same state only while their devices compute the same bits; before
// every batch they check that they do (one sum of a fingerprint of the gather's partials, from
// which every choice of the next batch follows) and agree on the time limit in the same sum.
// A difference ends every process with the same error, not a hang or a silently wrong answer.
// Returns whether any process reached the time limit.
bool agreeBeforeBatch(const ProcessGroup& group, const std::vector<UnshotPartial>& partials, bool timeUp,
                      std::uint64_t batch) {
    const std::uint64_t fingerprint = Fnv1a().add(partials.data(), partials.size() * sizeof(UnshotPartial)).value();
    std::vector<std::uint64_t> words = {fingerprint, timeUp ? 1u : 0u};
    group.sum(words);
    if (words[0] != fingerprint * static_cast<std::uint64_t>(group.size()))
        throw RuntimeFailure("the ranks' solver states differ before batch " + std::to_string(batch + 1) +
                             ": their devices do not compute the same bits (docs/devices.md); give every rank the "
                             "same kind of device");
    return words[1] > 0;
}

// Why the solve stops before the next batch, if it does. The tolerance and the shot count are
// the same on every process; `timeUp` is agreed (the first process to reach it stops all).
std::optional<StopReason> stopReason(const ProgressiveOptions& options, const SolveHooks& hooks, double unshotFraction,
                                     std::uint64_t shots, bool timeUp) {
    if (unshotFraction < options.tolerance) return StopReason::Tolerance;
    if (options.maxShots > 0 && shots >= options.maxShots) return StopReason::MaxShots;
    if (timeUp) return StopReason::TimeLimit;
    if (hooks.interrupted && hooks.interrupted()) return StopReason::Interrupted;
    return std::nullopt;
}

// The per-element radiosity and the energy balance from the device's final state. The light the
// shots brought to the elements of small patches is pooled over their clusters as far as their
// own hits cannot tell it apart (solver/cluster_receivers.h); the direct light of emitters the solver
// does not shoot has samples of its own on every element and is kept as it is. The energy
// balance is the device's, before pooling (which moves power only between elements of one
// material). `hitPower`: what one ray of a shot carries at most, summed over channels, in device
// units.
void collect(const PreparedScene& scene, const ElementMesh& elements, const InitialState& state,
             const DirectLight& direct, const PatchClusters& clusters, double hitPower,
             const std::vector<rad_float4>& incident, const std::vector<rad_float4>& unshot,
             const std::vector<rad_float4>& caustic, const SolverState& progress, ProgressiveResult& result) {
    const std::vector<glm::vec3> exitance = scene.patches().exitance();
    const std::vector<Element>& list = elements.elements();
    const std::size_t elementCount = list.size();
    std::vector<glm::dvec3> arrived(elementCount), shot(elementCount);  // W; the shots' part in device units
    for (std::size_t e = 0; e < elementCount; ++e) {
        const std::uint32_t p = list[e].patch;
        const glm::dvec3 rho(state.reflectance[p].s[0], state.reflectance[p].s[1], state.reflectance[p].s[2]);
        arrived[e] = glm::dvec3(incident[e].s[0], incident[e].s[1], incident[e].s[2]) / state.scale;
        result.energy.absorbed += (glm::dvec3(1.0) - rho) * arrived[e];
        shot[e] = glm::max(arrived[e] - (direct.empty() ? glm::dvec3(0.0) : direct.arrived[e]), glm::dvec3(0.0)) *
                  state.scale;
    }
    const PooledReceivers pooled = poolReceivers(elements, clusters, shot, hitPower);
    result.pooled = pooled.pooled;
    // Where an element got no hit, what it may lack is about one hit over the receiver its hits
    // were read in, shared by area: pooled in a cluster of several patches, that hit's light over
    // the cluster; on its own, one hit over its patch lands on it with the chance of its share of
    // the patch's area, a variance of (hit / its area)^2 times that share.
    std::vector<double> clusterArea(scene.patches().size(), 0.0), patchArea(scene.patches().size(), 0.0);
    for (const Element& element : list) patchArea[element.patch] += element.area;
    for (std::size_t c = 0; c < clusters.count(); ++c) {
        if (clusters.size(c) < 2) continue;
        double area = 0.0;
        for (std::uint32_t m = clusters.start()[c]; m < clusters.start()[c + 1]; ++m)
            for (std::uint32_t e = elements.elementStart()[clusters.members()[m]];
                 e < elements.elementStart()[clusters.members()[m] + 1]; ++e)
                area += list[e].area;
        for (std::uint32_t m = clusters.start()[c]; m < clusters.start()[c + 1]; ++m)
            clusterArea[clusters.members()[m]] = area;
    }
    result.radiosity.resize(elementCount);
    result.incident.resize(elementCount);
    result.receivers.clear();
    for (std::size_t e = 0; e < elementCount; ++e) {
        const Element& element = list[e];
        const std::uint32_t p = element.patch;
        const glm::dvec3 rho(state.reflectance[p].s[0], state.reflectance[p].s[1], state.reflectance[p].s[2]);
        // W; bitwise the device's where the element keeps its own value
        const glm::dvec3 received =
            pooled.power[e] == shot[e] ? arrived[e] : arrived[e] - shot[e] / state.scale + pooled.power[e] / state.scale;
        const glm::dvec3 reflected = element.area > 0.0f ? rho * received / static_cast<double>(element.area) : glm::dvec3(0.0);
        result.radiosity[e] = glm::vec3(glm::dvec3(exitance[p]) + reflected);
        result.incident[e] = glm::vec3(received);
        // The noise of its value, in the channels it reflects: the shots' part as uncertain as
        // the hits it rests on say (pooled: cluster_receivers.h), the direct light as its rays'
        // spread says (exact where it was not sampled: the punctual lights' closed form); an
        // element that reflects no channel (black, mirrors, glass) is no receiver.
        ReceiverNoise r;
        double reflectance = 0.0, ofShots = 0.0, ofDirect = 0.0;
        const double directSum = direct.empty() ? 0.0 : direct.arrived[e].x + direct.arrived[e].y + direct.arrived[e].z;
        for (int c = 0; c < 3; ++c) {
            if (!(rho[c] > 0.01)) continue;
            reflectance += rho[c];
            r.radiosity += result.radiosity[e][c];
            ofShots += rho[c] * pooled.power[e][c] / state.scale;
            if (!direct.empty()) ofDirect += rho[c] * direct.arrived[e][c];
        }
        if (!(reflectance > 0.0) || !(element.area > 0.0f)) continue;
        r.area = element.area;
        r.hit = shot[e].x + shot[e].y + shot[e].z > 0.0;
        const double oneHit = reflectance / 3.0 * hitPower / state.scale;
        const double fromShots = pooled.hits[e] > 0.0 ? ofShots / r.area / std::sqrt(pooled.hits[e])
                                 : clusterArea[p] > 0.0 ? oneHit / clusterArea[p]
                                                        : oneHit / std::sqrt(r.area * patchArea[p]);
        // Its variance is of the sum over channels: reflected as the direct light's channels are
        // (evenly where none arrived).
        const double fromDirect = direct.variance.empty() ? 0.0
                                  : std::sqrt(direct.variance[e]) / r.area *
                                        (directSum > 0.0 ? ofDirect / directSum : reflectance / 3.0);
        r.noise = std::sqrt(fromShots * fromShots + fromDirect * fromDirect);
        result.receivers.push_back(r);
    }
    result.caustic.resize(caustic.size());
    for (std::size_t e = 0; e < caustic.size(); ++e)
        result.caustic[e] = glm::vec3(glm::dvec3(caustic[e].s[0], caustic[e].s[1], caustic[e].s[2]) / state.scale);
    for (const rad_float4& left : unshot)
        result.energy.unshot += glm::dvec3(left.s[0], left.s[1], left.s[2]) / state.scale;
    result.energy.absorbed += progress.absorbedByBacks / state.scale;
    result.energy.absorbedByBacks = progress.absorbedByBacks / state.scale;
    result.energy.escaped = progress.escaped / state.scale;
    result.tallies = progress.tallies;
}

}  // namespace

namespace {

// A progressive solve on the device, batch by batch: what it runs on (the shooter, the device
// state, the amplification it measures, each shooter's samples) and the steps of a batch. The
// caller decides when to stop and when to save a state.
class BatchLoop {
public:
    BatchLoop(const PreparedScene& scene, const ElementMesh& elements, const ProgressiveOptions& options,
              const ProcessGroup& group, const std::vector<glm::vec3>& reflectance, const InitialState& initial,
              const glm::dvec3& toShoot, const PatchClusters& clusters, std::vector<std::uint64_t> samplesUsed,
              SolverState& progress, ProgressiveResult& result)
        : scene_(scene),
          options_(options),
          group_(group),
          initial_(initial),
          progress_(progress),
          result_(result),
          shooter_(scene.compute(), scene.device()),
          deviceElements_(scene.device().elements(elements)),
          counters_(counterLayout(scene.compute(), options, elements, initial)),
          clusters_(clusters),
          maxShooters_(maxShooters(options, clusters_)),
          state_(scene.compute(), *deviceElements_, initial.reflectance, scene.patches().area, initial.incident,
                 initial.unshot, initial.caustic, clusters_, maxShooters_, counters_.sets),
          flow_(toShoot, reflectedArea(reflectance, scene.patches()), maxReflectance(reflectance), progress.shot,
                options.amplificationThreshold, elements.elements().size() == scene.patches().size()),
          samples_(std::move(samplesUsed), options.seed) {
        result.counters = counters_;
        result.clusters = clusters_.count();
    }

    // Before the first batch: with no power delivered, the gather only reduces the unshot power.
    std::vector<UnshotPartial> start() {
        std::vector<UnshotPartial> partials = gather(glm::vec3(0.0f));
        measure(partials);
        return partials;
    }

    // One batch: the strongest shooters shoot, their receivers gather; `partials` become the
    // gather's. False when what is left is below the quantum, so no shot can move it.
    bool shoot(std::vector<UnshotPartial>& partials) {
        const std::vector<Shooter> shooters = chooseShooters(partials);
        if (shooters.empty()) return false;
        // Every process advances every shooter's samples; each shoots only its own share.
        std::vector<std::uint64_t> cost(shooters.size());
        for (std::size_t k = 0; k < shooters.size(); ++k) cost[k] = shooters[k].rays;
        const std::vector<std::uint32_t> owner = divideByCost(cost, group_.size());
        std::vector<RayRequest> requests;
        for (std::size_t k = 0; k < shooters.size(); ++k) {
            const RayRequest request =
                samples_.request(shooters[k].patch, shooters[k].rays, static_cast<std::uint32_t>(k));
            if (owner[k] == static_cast<std::uint32_t>(group_.rank())) requests.push_back(request);
            progress_.tallies.rays += shooters[k].rays;
        }
        // shooters and launches stay alive until gather()'s blocking read has returned.
        const std::vector<Launch> launches = planLaunches(requests, RayShooter::kMaxRaysPerLaunch);
        state_.writeShooters(shooters);
        state_.prepareShooters(static_cast<std::uint32_t>(shooters.size()));
        shooter_.deliverPower(launches, state_.shooters(), state_.power(), *deviceElements_, state_.elementCdf(),
                              counters_, state_.columns(), state_.touched());
        if (group_.size() > 1) {
            scene_.compute().finish();  // the shots first, so the clock times only the sum
            Stopwatch summing;
            state_.sumPowerOver(group_);
            result_.sumSeconds += summing.seconds();
        }
        state_.takeShots(static_cast<std::uint32_t>(shooters.size()));
        partials = gather(glm::vec3(0.0f));
        measure(partials);
        progress_.shot = flow_.shot();
        progress_.tallies.shots += shots_;
        ++progress_.tallies.batches;
        return true;
    }

    // The state to save, `seconds` into the solve.
    SolverState snapshot(double seconds) {
        SolverState saved = progress_;
        saved.seconds = seconds;
        const std::size_t patchCount = initial_.unshot.size(), elementCount = initial_.incident.size();
        const std::vector<rad_float4> in = state_.readIncident(), left = state_.readUnshot();
        saved.incident.resize(elementCount);
        saved.unshot.resize(patchCount);
        for (std::size_t p = 0; p < patchCount; ++p)
            for (int c = 0; c < 4; ++c) saved.unshot[p][c] = left[p].s[c];
        for (std::size_t e = 0; e < elementCount; ++e)
            for (int c = 0; c < 4; ++c) saved.incident[e][c] = in[e].s[c];
        const std::vector<rad_float4> caustic = state_.readCaustic();
        saved.caustic.resize(caustic.size());
        for (std::size_t e = 0; e < caustic.size(); ++e)
            for (int c = 0; c < 4; ++c) saved.caustic[e][c] = caustic[e].s[c];
        saved.samplesUsed = samples_.used();
        return saved;
    }

    // The solve's result from the device's final state.
    void finish(const ElementMesh& elements, const DirectLight& direct) {
        const double hitPower = initial_.emitted * result_.rayPowerScale / static_cast<double>(std::max<std::uint64_t>(1, options_.rays));
        // Without pooling every element keeps its own: no clusters to pool over.
        const PatchClusters none;
        const PatchClusters& receivers = options_.pooling ? clusters_ : none;
        collect(scene_, elements, initial_, direct, receivers, hitPower, state_.readIncident(), state_.readUnshot(),
                state_.readCaustic(), progress_, result_);
    }

private:
    // A quantum of 2^-48 of the device units: shots sum exactly in 64-bit integers with room to
    // spare, and rounding every ray loses under 1e-7 of the power.
    static constexpr float kQuantum = 0x1p-48f;

    static CounterLayout counterLayout(ComputeContext& compute, const ProgressiveOptions& options,
                                       const ElementMesh& elements, const InitialState& initial) {
        const std::uint32_t columns =
            powerColumns(static_cast<std::uint32_t>(elements.elements().size()), !initial.caustic.empty());
        return options.counters ? options.counters->normalised()
                                : CounterLayout::forDevice(compute, powerSetWords(columns) * sizeof(rad_uint));
    }

    // The most shooters (patches) of one batch: the clusters' members, up to 16 times the
    // clusters a batch shoots, and at least the largest cluster.
    static std::uint32_t maxShooters(const ProgressiveOptions& options, const PatchClusters& clusters) {
        if (clusters.isIdentity()) return options.maxShootersPerBatch;
        return std::max(options.maxShootersPerBatch * std::min(clusters.largest(), 16u), clusters.largest());
    }

    // The batch's shooters, each with its rays and power; none when what they would take is 0.
    // A cluster's rays are shared among its patches by their power (shareRays), each a shooter.
    std::vector<Shooter> chooseShooters(const std::vector<UnshotPartial>& partials) {
        std::uint32_t batch = options_.maxShootersPerBatch;
        if (options_.maxShots > 0)
            batch = static_cast<std::uint32_t>(std::min<std::uint64_t>(batch, options_.maxShots - progress_.tallies.shots));
        std::vector<Candidate> chosen = selectShooters(partials, batch, options_.batchPowerRatio);
        // The clusters that fit in the shooters' array, and the patches of those of more than one.
        std::vector<rad_uint> members;
        std::uint32_t records = 0;
        for (std::size_t k = 0; k < chosen.size(); ++k) {
            const std::uint32_t size = clusters_.size(chosen[k].cluster);
            if (records + size > maxShooters_) {
                chosen.resize(k);
                break;
            }
            records += size;
            if (size > 1)
                for (std::uint32_t m = clusters_.start()[chosen[k].cluster]; m < clusters_.start()[chosen[k].cluster + 1]; ++m)
                    members.push_back(clusters_.members()[m]);
        }
        const std::vector<rad_float4> memberPowers = state_.memberPowers(members);
        std::vector<Shooter> shooters;
        double taken = 0.0;
        const double rayPower = initial_.emitted * flow_.rayPowerScale();  // a shot of this much casts options.rays
        result_.rayPowerScale = std::max(result_.rayPowerScale, flow_.rayPowerScale());
        std::size_t next = 0;  // the next cluster member's place in `members`
        std::vector<double> magnitudes;
        for (const Candidate& c : chosen) {
            const std::uint32_t rays = raysForShot(c.total, rayPower, options_.rays, options_.minRays);
            const std::uint32_t size = clusters_.size(c.cluster);
            if (size == 1) {
                shooters.push_back(makeShooter(clusters_.members()[clusters_.start()[c.cluster]], c.power, rays, kQuantum));
            } else {
                magnitudes.assign(size, 0.0);
                for (std::uint32_t m = 0; m < size; ++m) {
                    const rad_float4& p = memberPowers[next + m];
                    magnitudes[m] = std::fabs(static_cast<double>(p.s[0])) + std::fabs(p.s[1]) + std::fabs(p.s[2]);
                }
                const std::vector<std::uint32_t> shares = shareRays(magnitudes, rays);
                for (std::uint32_t m = 0; m < size; ++m, ++next) {
                    if (shares[m] == 0) continue;
                    const rad_float4& p = memberPowers[next];
                    shooters.push_back(makeShooter(members[next], glm::vec3(p.s[0], p.s[1], p.s[2]), shares[m], kQuantum));
                }
            }
        }
        for (const Shooter& s : shooters) {
            taken += std::fabs(static_cast<double>(s.taken[0])) + std::fabs(s.taken[1]) + std::fabs(s.taken[2]);
            flow_.addShot(s);
        }
        shots_ = chosen.size();
        if (!(taken > 0.0)) shooters.clear();
        return shooters;
    }

    std::vector<UnshotPartial> gather(const glm::vec3& overshoot) {
        return state_.gather(kQuantum, overshoot, progress_.escaped, progress_.absorbedByBacks);
    }

    // After every gather: the amplification measured from its sums, and, where the solve
    // overshoots, the patches ranked again by what they now have to shoot (a gather with
    // nothing delivered changes nothing else), so a solve resumed from any batch ranks alike.
    void measure(std::vector<UnshotPartial>& partials) {
        flow_.update(partials);
        const glm::vec3 k = flow_.overshoot();
        if (k != glm::vec3(0.0f)) partials = gather(k);
    }

    const PreparedScene& scene_;
    const ProgressiveOptions& options_;
    const ProcessGroup& group_;
    const InitialState& initial_;
    SolverState& progress_;
    ProgressiveResult& result_;
    RayShooter shooter_;
    const std::shared_ptr<const DeviceElements> deviceElements_;
    const CounterLayout counters_;
    const PatchClusters& clusters_;
    const std::uint32_t maxShooters_;
    std::size_t shots_ = 0;  // clusters the last batch shot
    DeviceState state_;
    Amplification flow_;
    SampleCounters samples_;
};

}  // namespace

ProgressiveResult ProgressiveSolver::solve(const ProgressiveOptions& options, const SolveHooks& hooks,
                                           const SolverState* resume) {
    Stopwatch clock;
    ProgressiveResult result;
    const PatchClusters clusters =
        options.clusters ? PatchClusters::of(scene_.mesh()) : PatchClusters::identity(scene_.patches().size());
    const DirectLight direct =
        directLight(scene_, elements_, options.seed, SpecularModel::follow, &clusters,
                    static_cast<double>(options.directLightRays > 0 ? options.directLightRays : options.rays) /
                        static_cast<double>(ProgressiveOptions{}.rays));
    const std::vector<glm::vec3> reflectance = solveReflectance(scene_);
    InitialState initial = initialState(scene_, reflectance, elements_, direct, result);
    SolverState progress;  // the tallies; its per-patch vectors are filled only to save a state
    std::vector<std::uint64_t> samplesUsed(scene_.patches().size(), 0);
    glm::dvec3 toShoot(0.0);  // per channel, before a resumed state replaces the unshot power
    for (const rad_float4& power : initial.unshot)
        for (int c = 0; c < 3; ++c) toShoot[c] += static_cast<double>(power.s[c]);
    if (resume) resumeFrom(*resume, initial, samplesUsed, progress);
    else if (!direct.empty()) {
        progress.escaped += direct.escaped * initial.scale;
        progress.absorbedByBacks += direct.absorbedByBacks * initial.scale;
    }
    const ProcessGroup& group = hooks.group ? *hooks.group : oneProcess();
    BatchLoop loop(scene_, elements_, options, group, reflectance, initial, toShoot, clusters, std::move(samplesUsed),
                   progress, result);
    double lastCheckpoint = 0.0;
    std::vector<UnshotPartial> partials = loop.start();
    for (;;) {
        result.unshotFraction = initial.emitted > 0.0 ? unshotTotal(partials) / initial.emitted : 0.0;
        if (hooks.progress) hooks.progress({progress.tallies.shots, progress.tallies.rays, result.unshotFraction, clock.seconds()});
        bool timeUp = options.timeLimit > 0.0 && clock.seconds() >= options.timeLimit;
        if (group.size() > 1) timeUp = agreeBeforeBatch(group, partials, timeUp, progress.tallies.batches);
        if (const auto reason = stopReason(options, hooks, result.unshotFraction, progress.tallies.shots, timeUp)) {
            result.stopped = *reason;
            break;
        }
        if (hooks.checkpoint && hooks.checkpointEvery > 0.0 && clock.seconds() - lastCheckpoint >= hooks.checkpointEvery) {
            hooks.checkpoint(loop.snapshot(progress.seconds + clock.seconds()));
            lastCheckpoint = clock.seconds();
        }
        if (!loop.shoot(partials)) {
            result.stopped = StopReason::Tolerance;
            break;
        }
    }
    if (hooks.checkpoint) hooks.checkpoint(loop.snapshot(progress.seconds + clock.seconds()));
    loop.finish(elements_, direct);
    result.kernelSeconds = scene_.compute().takeKernelSeconds();
    result.seconds = progress.seconds + clock.seconds();
    return result;
}

}  // namespace rad
