#include "solver/progressive_solver.h"

#include <algorithm>
#include <cmath>

#include "mesh/device_elements.h"
#include "cl/buffers.h"
#include "cl/error.h"
#include "formfactor/launch_plan.h"
#include "formfactor/ray_shooter.h"
#include "solver/shooter_selection.h"
#include "util/error.h"
#include "util/stopwatch.h"
#include "shared_math.h"

static_assert(sizeof(Shooter) == 48, "Shooter must match the kernels' layout");
static_assert(sizeof(UnshotPartial) == 32, "UnshotPartial must match the kernels' layout");

namespace rad {
namespace {

// Distinguishes the shooters' sample sequences from other estimators' with the same seed.
constexpr std::uint32_t kShooterStream = 0x5f5e0002u;
// Gather work items: enough to keep a GPU busy, few enough that their partials are a small read.
constexpr std::uint32_t kMaxGatherItems = 4096;

// The device side of one solve: per-patch state and the batch's buffers.
class DeviceState {
public:
    // Per patch: reflectance and unshot power; per element: incident power (w: the element's
    // own unshot power, summed over channels, that decides where its patch's rays start).
    DeviceState(ComputeContext& compute, const DeviceElements& elements, const std::vector<cl_float4>& reflectance,
                const std::vector<cl_float4>& incident, const std::vector<cl_float4>& unshot, std::uint32_t maxShooters)
        : compute_(compute),
          elements_(elements),
          patchCount_(static_cast<std::uint32_t>(reflectance.size())),
          elementCount_(static_cast<std::uint32_t>(incident.size())),
          gatherItems_(std::clamp<std::uint32_t>(patchCount_ / 4, 1, kMaxGatherItems)) {
        const std::uint64_t perPatch = std::uint64_t{patchCount_} * sizeof(cl_float4);
        const std::uint64_t perElement = std::uint64_t{elementCount_} * sizeof(cl_float4);
        const std::uint64_t power = (std::uint64_t{elementCount_} + 2) * 6 * sizeof(cl_uint);
        const std::uint64_t cdf = std::max<std::uint64_t>(1, elementCount_) * sizeof(cl_uint);
        reservation_ = compute.reserve(2 * perPatch + perElement + cdf + power + sizeof(Shooter) * std::max(1u, maxShooters) +
                                           sizeof(UnshotPartial) * gatherItems_,
                                       std::max({perPatch, perElement, power}), "the solver's per-patch state");
        try {
            reflectance_ = uploadBuffer(compute, reflectance, "patch reflectances");
            unshot_ = uploadBuffer(compute, unshot, "unshot power", CL_MEM_READ_WRITE);
            incident_ = uploadBuffer(compute, incident, "incident power", CL_MEM_READ_WRITE);
            power_ = uploadBuffer(compute, std::vector<cl_uint>((std::size_t{elementCount_} + 2) * 6, 0u), "delivered power",
                                  CL_MEM_READ_WRITE);
            elementCdf_ = allocateBuffer<cl_uint>(compute, elementCount_, "element shares");
            shooters_ = allocateBuffer<Shooter>(compute, maxShooters, "shooters", CL_MEM_READ_ONLY);
            partials_ = allocateBuffer<UnshotPartial>(compute, gatherItems_, "unshot partials", CL_MEM_WRITE_ONLY);
            lost_ = allocateBuffer<cl_float4>(compute, 2, "lost power", CL_MEM_WRITE_ONLY);
            cl::Program& program = compute.program("progressive.cl");
            prepare_ = cl::Kernel(program, "prepare_shooters");
            take_ = cl::Kernel(program, "take_shots");
            gather_ = cl::Kernel(program, "gather");
        } catch (const cl::Error& e) {
            throwDeviceError(e, "allocating the solver's device state for " + std::to_string(patchCount_) + " patches");
        }
    }

    cl::Buffer& power() { return power_; }
    const cl::Buffer& shooters() const { return shooters_; }
    const cl::Buffer& elementCdf() const { return elementCdf_; }

    // Not blocking: `shooters` must stay alive until the batch's gather() has returned.
    void writeShooters(const std::vector<Shooter>& shooters) { enqueueWrite(compute_, shooters_, shooters); }

    // Before the batch's shots: where on its patch each shooter's rays start.
    void prepareShooters(std::uint32_t count) {
        setKernelArgs(prepare_, 0, shooters_, static_cast<cl_uint>(count), elements_.elementStart, incident_,
                      elements_.frames, elementCdf_);
        compute_.launch(prepare_, count);
    }

    void takeShots(std::uint32_t count) {
        setKernelArgs(take_, 0, shooters_, static_cast<cl_uint>(count), unshot_);
        compute_.launch(take_, count);
    }

    // Delivers the batch's power and reduces the unshot power; returns the partials and adds
    // what left the scene and what black backs took to `escaped` and `backs`.
    std::vector<UnshotPartial> gather(float quantum, glm::dvec3& escaped, glm::dvec3& backs) {
        setKernelArgs(gather_, 0, power_, quantum, reflectance_, incident_, unshot_, elements_.elementStart,
                      static_cast<cl_uint>(patchCount_), static_cast<cl_uint>(elementCount_),
                      static_cast<cl_uint>(gatherItems_), partials_, lost_);
        compute_.launch(gather_, gatherItems_);
        std::vector<UnshotPartial> partials(gatherItems_);
        enqueueRead(compute_, partials_, partials);
        const std::vector<cl_float4> lost = readBuffer<cl_float4>(compute_, lost_, 2);
        for (int c = 0; c < 3; ++c) {
            escaped[c] += lost[0].s[c];
            backs[c] += lost[1].s[c];
        }
        return partials;
    }

    std::vector<cl_float4> readIncident() { return readBuffer<cl_float4>(compute_, incident_, elementCount_); }
    std::vector<cl_float4> readUnshot() { return readBuffer<cl_float4>(compute_, unshot_, patchCount_); }

private:
    ComputeContext& compute_;
    const DeviceElements& elements_;
    std::uint32_t patchCount_, elementCount_;
    std::uint32_t gatherItems_;
    MemoryReservation reservation_;
    cl::Buffer reflectance_, unshot_, incident_, power_, elementCdf_, shooters_, partials_, lost_;
    cl::Kernel prepare_, take_, gather_;
};

// Keeps one Sobol sequence per shooter over all its shots; past 2^32 samples a new scramble
// starts a fresh sequence.
class SampleCounters {
public:
    SampleCounters(std::vector<std::uint64_t> used, std::uint32_t seed)
        : used_(std::move(used)), stream_(rad_hash2(seed, kShooterStream)) {}
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

ProgressiveResult ProgressiveSolver::solve(const ProgressiveOptions& options, const SolveHooks& hooks,
                                           const SolverState* resume) {
    Stopwatch clock;
    ComputeContext& compute = scene_.compute();
    const PatchSystem& system = scene_.patches();
    const std::size_t patchCount = system.size();
    const std::vector<glm::vec3> exitance = system.exitance();
    ProgressiveResult result;
    for (std::size_t p = 0; p < patchCount; ++p)
        result.energy.emitted += glm::dvec3(exitance[p]) * static_cast<double>(system.area[p]);
    const double strongest = std::max({result.energy.emitted.x, result.energy.emitted.y, result.energy.emitted.z});
    if (!(strongest > 0.0)) throw InputError("nothing in the scene emits light: there is nothing to solve");
    // The device works in units that put the strongest channel's emitted power in [1, 2): a
    // power of two, so scaling is exact, and single precision is spent on the light's own range
    // however bright or faint the scene is in watts.
    int exponent = 0;
    std::frexp(strongest, &exponent);
    const double scale = std::ldexp(1.0, 1 - exponent);
    // A quantum of 2^-48 of that: shots sum exactly in 64-bit integers with room to spare, and
    // rounding every ray loses under 1e-7 of the power.
    const float quantum = 0x1p-48f;
    const std::size_t elementCount = elements_.elements().size();
    std::vector<cl_float4> reflectance(patchCount), unshot(patchCount), incident(elementCount, cl_float4{{0, 0, 0, 0}});
    double emitted = 0.0;  // in device units, summed over channels
    for (std::size_t p = 0; p < patchCount; ++p) {
        const glm::dvec3 power = glm::dvec3(exitance[p]) * static_cast<double>(system.area[p]) * scale;
        reflectance[p] = float4Of(system.reflectance[p]);
        unshot[p] = float4Of(glm::vec3(power));
        emitted += static_cast<double>(unshot[p].s[0]) + unshot[p].s[1] + unshot[p].s[2];
    }
    // What each element emits is its share of its patch's, by area (scale^2 of the patch's).
    for (std::size_t e = 0; e < elementCount; ++e) {
        const Element& element = elements_.elements()[e];
        const cl_float4& power = unshot[element.patch];
        incident[e].s[3] = (power.s[0] + power.s[1] + power.s[2]) * element.frame.scale * element.frame.scale;
    }

    SolverState progress;  // the tallies; its per-patch vectors are filled only to save a state
    std::vector<std::uint64_t> samplesUsed(patchCount, 0);
    if (resume) {
        if (resume->incident.size() != elementCount || resume->unshot.size() != patchCount ||
            resume->samplesUsed.size() != patchCount)
            throw InputError("the saved state holds " + std::to_string(resume->unshot.size()) + " patches and " +
                             std::to_string(resume->incident.size()) + " elements; this mesh has " +
                             std::to_string(patchCount) + " and " + std::to_string(elementCount));
        for (std::size_t p = 0; p < patchCount; ++p)
            for (int c = 0; c < 4; ++c) unshot[p].s[c] = resume->unshot[p][c];
        for (std::size_t e = 0; e < elementCount; ++e)
            for (int c = 0; c < 4; ++c) incident[e].s[c] = resume->incident[e][c];
        samplesUsed = resume->samplesUsed;
        progress.escaped = resume->escaped;
        progress.absorbedByBacks = resume->absorbedByBacks;
        progress.shots = resume->shots;
        progress.rays = resume->rays;
        progress.batches = resume->batches;
        progress.seconds = resume->seconds;
    }

    RayShooter shooter(compute, scene_.device());
    const DeviceElements deviceElements(compute, elements_);
    DeviceState state(compute, deviceElements, reflectance, incident, unshot, options.maxShootersPerBatch);
    SampleCounters samples(std::move(samplesUsed), options.seed);
    auto snapshot = [&]() {
        SolverState saved = progress;
        saved.seconds = progress.seconds + clock.seconds();
        const std::vector<cl_float4> in = state.readIncident(), left = state.readUnshot();
        saved.incident.resize(elementCount);
        saved.unshot.resize(patchCount);
        for (std::size_t p = 0; p < patchCount; ++p)
            for (int c = 0; c < 4; ++c) saved.unshot[p][c] = left[p].s[c];
        for (std::size_t e = 0; e < elementCount; ++e)
            for (int c = 0; c < 4; ++c) saved.incident[e][c] = in[e].s[c];
        saved.samplesUsed = samples.used();
        return saved;
    };
    double lastCheckpoint = 0.0;
    try {
        // With no power delivered, gather only reduces the unshot power.
        std::vector<UnshotPartial> partials = state.gather(quantum, progress.escaped, progress.absorbedByBacks);
        for (;;) {
            result.unshotFraction = unshotTotal(partials) / emitted;
            if (hooks.progress) hooks.progress({progress.shots, progress.rays, result.unshotFraction, clock.seconds()});
            if (result.unshotFraction < options.tolerance) {
                result.stopped = StopReason::Tolerance;
                break;
            }
            if (options.maxShots > 0 && progress.shots >= options.maxShots) {
                result.stopped = StopReason::MaxShots;
                break;
            }
            if (options.timeLimit > 0.0 && clock.seconds() >= options.timeLimit) {
                result.stopped = StopReason::TimeLimit;
                break;
            }
            if (hooks.interrupted && hooks.interrupted()) {
                result.stopped = StopReason::Interrupted;
                break;
            }
            if (hooks.checkpoint && hooks.checkpointEvery > 0.0 && clock.seconds() - lastCheckpoint >= hooks.checkpointEvery) {
                hooks.checkpoint(snapshot());
                lastCheckpoint = clock.seconds();
            }
            std::uint32_t batch = options.maxShootersPerBatch;
            if (options.maxShots > 0)
                batch = static_cast<std::uint32_t>(std::min<std::uint64_t>(batch, options.maxShots - progress.shots));
            const std::vector<Candidate> chosen = selectShooters(partials, batch, options.batchPowerRatio);
            std::vector<Shooter> shooters;
            std::vector<RayRequest> requests;
            double taken = 0.0;
            for (const Candidate& c : chosen) {
                const std::uint32_t rays = raysForShot(c.total, emitted, options.rays, options.minRays);
                shooters.push_back(makeShooter(c.patch, c.power, rays, quantum));
                taken += static_cast<double>(shooters.back().taken[0]) + shooters.back().taken[1] + shooters.back().taken[2];
            }
            if (!(taken > 0.0)) {  // what is left is below the quantum: no shot can move it
                result.stopped = StopReason::Tolerance;
                break;
            }
            for (std::size_t k = 0; k < shooters.size(); ++k) {
                requests.push_back(samples.request(shooters[k].patch, shooters[k].rays, static_cast<std::uint32_t>(k)));
                progress.rays += shooters[k].rays;
            }
            // shooters and launches stay alive until gather()'s blocking read has returned.
            const std::vector<Launch> launches = planLaunches(requests, RayShooter::kMaxRaysPerLaunch);
            state.writeShooters(shooters);
            state.prepareShooters(static_cast<std::uint32_t>(shooters.size()));
            shooter.deliverPower(launches, state.shooters(), state.power(), deviceElements, state.elementCdf());
            state.takeShots(static_cast<std::uint32_t>(shooters.size()));
            partials = state.gather(quantum, progress.escaped, progress.absorbedByBacks);
            progress.shots += shooters.size();
            ++progress.batches;
        }
        if (hooks.checkpoint) hooks.checkpoint(snapshot());
        const std::vector<cl_float4> in = state.readIncident(), left = state.readUnshot();
        result.radiosity.resize(elementCount);
        result.incident.resize(elementCount);
        for (std::size_t e = 0; e < elementCount; ++e) {
            const Element& element = elements_.elements()[e];
            const std::uint32_t p = element.patch;
            const glm::dvec3 rho(reflectance[p].s[0], reflectance[p].s[1], reflectance[p].s[2]);
            const glm::dvec3 arrived = glm::dvec3(in[e].s[0], in[e].s[1], in[e].s[2]) / scale;  // W
            const glm::dvec3 reflected = element.area > 0.0f ? rho * arrived / static_cast<double>(element.area) : glm::dvec3(0.0);
            result.radiosity[e] = glm::vec3(glm::dvec3(exitance[p]) + reflected);
            result.incident[e] = glm::vec3(arrived);
            result.energy.absorbed += (glm::dvec3(1.0) - rho) * arrived;
        }
        for (std::size_t p = 0; p < patchCount; ++p)
            result.energy.unshot += glm::dvec3(left[p].s[0], left[p].s[1], left[p].s[2]) / scale;
    } catch (const cl::Error& e) {
        throwDeviceError(e, "progressive refinement");
    }
    result.energy.absorbed += progress.absorbedByBacks / scale;
    result.energy.absorbedByBacks = progress.absorbedByBacks / scale;
    result.energy.escaped = progress.escaped / scale;
    result.shots = progress.shots;
    result.rays = progress.rays;
    result.batches = progress.batches;
    result.kernelSeconds = compute.takeKernelSeconds();
    result.seconds = progress.seconds + clock.seconds();
    return result;
}

}  // namespace rad
