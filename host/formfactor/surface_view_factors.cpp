#include "formfactor/surface_view_factors.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "formfactor/ray_shooter.h"
#include "util/error.h"
#include "util/sample_streams.h"
#include "util/stopwatch.h"
#include "shared_math.h"

namespace rad {
namespace {

// Keeps the count matrix of one group of source surfaces within this many bytes.
constexpr std::uint64_t kCountBudget = 256ull << 20;

}  // namespace

std::uint64_t SurfaceViewFactors::hits(std::size_t from, std::size_t to) const {
    const auto& row = rows[from];
    const auto found = std::lower_bound(row.begin(), row.end(), std::make_pair(static_cast<std::uint32_t>(to), std::uint64_t{0}));
    return found != row.end() && found->first == to ? found->second : 0;
}

double SurfaceViewFactors::factor(std::size_t from, std::size_t to) const {
    return static_cast<double>(hits(from, to)) / static_cast<double>(raysPerSurface);
}

double SurfaceViewFactors::standardError(std::size_t from, std::size_t to) const {
    const double f = factor(from, to);
    return std::sqrt(f * (1.0 - f) / static_cast<double>(raysPerSurface));
}

SurfaceViewFactors computeSurfaceViewFactors(const PreparedScene& prepared, const ViewFactorOptions& options) {
    ComputeContext& compute = prepared.compute();
    const Mesh& mesh = prepared.mesh();
    const DeviceScene& scene = prepared.device();
    if (options.raysPerSurface < 1 || options.raysPerSurface > 0xFFFFFFFFull)
        throw InputError("--rays must be between 1 and 4294967295 per surface");
    const std::size_t surfaceCount = mesh.surfaces.size();
    SurfaceViewFactors result;
    result.raysPerSurface = options.raysPerSurface;
    for (const MeshSurface& s : mesh.surfaces) {
        result.names.push_back(s.name);
        result.areas.push_back(s.area);
    }
    result.rows.resize(surfaceCount);
    std::vector<std::uint64_t> perSurface(surfaceCount, 0);  // one row's sums, reused
    result.escaped.assign(surfaceCount, 0);
    result.blackBack.assign(surfaceCount, 0);

    RayShooter shooter(compute, scene);
    const std::uint64_t rowBytes = std::uint64_t{shooter.columns()} * sizeof(rad_uint);
    const std::uint64_t budget = std::min(kCountBudget, compute.description().maxAllocation);
    const std::size_t groupSize = static_cast<std::size_t>(std::max<std::uint64_t>(1, budget / rowBytes));

    // The surfaces this process shoots from (all of them, unless ranks divide them).
    const std::uint32_t ranks = std::max<std::uint32_t>(1, options.ranks);
    std::vector<std::size_t> own;
    for (std::size_t s = 0; s < surfaceCount; ++s)
        if (s % ranks == options.rank) own.push_back(s);

    std::vector<rad_uint> counts;
    DeviceArray<rad_uint> countArray;  // the rows of a group of surfaces, made for the first group
    for (std::size_t at = 0; at < own.size(); at += groupSize) {
        const std::size_t rows = std::min(groupSize, own.size() - at);
        std::vector<RayRequest> requests;
        for (std::size_t r = 0; r < rows; ++r) {
            const std::size_t surface = own[at + r];
            RayRequest request;
            request.firstTriangle = scene.surfaceRuns()[surface].first;
            request.triangleCount = scene.surfaceRuns()[surface].count;
            request.guide = scene.surfaceRuns()[surface].guide;
            request.rays = options.raysPerSurface;
            request.scramble =
                rad_hash2(rad_hash2(options.seed, kSurfaceRaysStream), static_cast<std::uint32_t>(surface));
            request.row = static_cast<std::uint32_t>(r);
            requests.push_back(request);
        }
        counts.assign(rows * shooter.columns(), 0);
        if (countArray.size() == 0)
            countArray = DeviceArray<rad_uint>::allocate(compute, std::min(groupSize, own.size()) * shooter.columns(),
                                                         "hit counts");
        Stopwatch clock;
        countArray.enqueueWrite(counts);  // counts outlives the blocking read below
        const std::vector<Launch> launches = planLaunches(requests, RayShooter::kMaxRaysPerLaunch);
        shooter.countHits(launches, countArray);  // launches outlive the blocking read below
        compute.finish();
        result.seconds.shooting += clock.seconds();
        clock = Stopwatch();
        counts = countArray.read(counts.size());
        result.seconds.reading += clock.seconds();
        clock = Stopwatch();
        for (std::size_t r = 0; r < rows; ++r) {
            const rad_uint* row = counts.data() + r * shooter.columns();
            const std::size_t from = own[at + r];
            for (std::uint32_t p = 0; p < mesh.patches.size(); ++p) perSurface[mesh.patches[p].surface] += row[p];
            for (std::uint32_t to = 0; to < surfaceCount; ++to)
                if (perSurface[to] != 0) {
                    result.rows[from].emplace_back(to, perSurface[to]);
                    perSurface[to] = 0;
                }
            result.escaped[from] = row[shooter.escapedColumn()];
            result.blackBack[from] = row[shooter.blackColumn()];
        }
        result.seconds.adding += clock.seconds();
    }
    return result;
}

std::vector<std::uint64_t> packOwnRows(const SurfaceViewFactors& f, std::uint32_t rank, std::uint32_t ranks) {
    // Per row: its surface, escaped, black backs, the number of entries, then (to, hits) pairs.
    std::vector<std::uint64_t> packed;
    for (std::size_t s = rank; s < f.size(); s += std::max<std::uint32_t>(1, ranks)) {
        packed.insert(packed.end(), {s, f.escaped[s], f.blackBack[s], f.rows[s].size()});
        for (const auto& [to, hits] : f.rows[s]) packed.insert(packed.end(), {to, hits});
    }
    return packed;
}

void unpackRows(SurfaceViewFactors& f, const std::vector<std::uint64_t>& packed) {
    std::size_t at = 0;
    const auto next = [&]() {
        if (at >= packed.size()) throw RuntimeFailure("the ranks' view-factor rows are cut short");
        return packed[at++];
    };
    while (at < packed.size()) {
        const std::uint64_t s = next();
        if (s >= f.size())
            throw RuntimeFailure("a rank sent a row for surface " + std::to_string(s) + " of " +
                                 std::to_string(f.size()));
        f.escaped[s] = next();
        f.blackBack[s] = next();
        const std::uint64_t entries = next();
        f.rows[s].clear();
        for (std::uint64_t k = 0; k < entries; ++k) {
            const auto to = static_cast<std::uint32_t>(next());
            f.rows[s].emplace_back(to, next());
        }
    }
}

SurfaceViewFactors poolSurfaceViewFactors(const std::vector<SurfaceViewFactors>& parts) {
    SurfaceViewFactors all = parts.front();
    all.raysPerSurface = 0;
    for (auto& row : all.rows) row.clear();
    std::fill(all.escaped.begin(), all.escaped.end(), 0);
    std::fill(all.blackBack.begin(), all.blackBack.end(), 0);
    for (const SurfaceViewFactors& p : parts) {
        all.raysPerSurface += p.raysPerSurface;
        for (std::size_t i = 0; i < p.size(); ++i) {
            all.escaped[i] += p.escaped[i];
            all.blackBack[i] += p.blackBack[i];
        }
    }
    for (std::size_t i = 0; i < all.size(); ++i) {
        std::map<std::uint32_t, std::uint64_t> hits;
        for (const SurfaceViewFactors& p : parts)
            for (const auto& [to, count] : p.rows[i]) hits[to] += count;
        all.rows[i].assign(hits.begin(), hits.end());
    }
    return all;
}

SurfaceViewFactors computeSurfaceViewFactors(const PreparedScene& scene, ViewFactorOptions options,
                                             const ProcessGroup& group) {
    options.rank = static_cast<std::uint32_t>(group.rank());
    options.ranks = static_cast<std::uint32_t>(group.size());
    SurfaceViewFactors factors = computeSurfaceViewFactors(scene, options);
    if (group.size() > 1) unpackRows(factors, group.allGather(packOwnRows(factors, options.rank, options.ranks)));
    return factors;
}

TargetErrorEstimate computeSurfaceViewFactorsToError(const PreparedScene& scene, double targetError, std::uint32_t seed,
                                                     std::uint64_t firstRays, std::uint64_t maxRays,
                                                     const ProcessGroup& group) {
    if (!(targetError > 0.0 && targetError < 0.5)) throw InputError("--target-error must lie in (0, 0.5)");
    constexpr std::uint64_t kMostPerCall = 0xFFFFFFFFull;
    std::vector<SurfaceViewFactors> parts;
    TargetErrorEstimate out;
    std::uint64_t cast = 0, next = std::max<std::uint64_t>(1, std::min(firstRays, maxRays));
    for (;;) {
        const std::uint64_t rays = std::min(next, kMostPerCall);
        parts.push_back(computeSurfaceViewFactors(
            scene, ViewFactorOptions{rays, rad_hash2(seed, static_cast<std::uint32_t>(parts.size()))}, group));
        cast += rays;
        ++out.rounds;
        out.factors = parts.size() == 1 ? parts.front() : poolSurfaceViewFactors(parts);
        // The most variance any factor has: F (1 - F) per ray.
        double variance = 0.0;
        for (std::size_t i = 0; i < out.factors.size(); ++i)
            for (const auto& [to, hits] : out.factors.rows[i]) {
                const double f = out.factors.factor(i, to);
                variance = std::max(variance, f * (1.0 - f));
            }
        out.largestError = std::sqrt(variance / static_cast<double>(cast));
        out.reached = out.largestError <= targetError;
        if (out.reached || cast >= maxRays) return out;
        // What the factors so far need in all, a tenth more for their own noise; at least a
        // quarter of what is cast, so the rounds stay few.
        const double needed =
            std::min(std::ceil(1.1 * variance / (targetError * targetError)), static_cast<double>(maxRays));
        const auto total = static_cast<std::uint64_t>(needed);
        next = std::max(total > cast ? total - cast : 1, cast / 4 + 1);
        next = std::min(next, maxRays - cast);
    }
}

std::vector<std::string> blackBackWarnings(const std::vector<std::string>& names, const std::vector<double>& shares,
                                           const std::string& consequence) {
    constexpr double kNoticeable = 1e-3;
    constexpr std::size_t kListed = 3;
    std::vector<std::size_t> lossy;
    for (std::size_t i = 0; i < shares.size(); ++i)
        if (shares[i] > kNoticeable) lossy.push_back(i);
    const auto percent = [&](std::size_t i) {
        char text[32];
        std::snprintf(text, sizeof text, "%.3g %%", 100.0 * shares[i]);
        return std::string(text);
    };
    const std::string what = " (a face turned away, or the inside of a closed part)";
    const std::string why = ": " + consequence + "; a face whose back should count must be double-sided";
    std::vector<std::string> warnings;
    if (lossy.size() <= kListed) {
        for (std::size_t i : lossy)
            warnings.push_back(percent(i) + " of the rays from '" + names[i] +
                               "' stop on the back of a single-sided face" + what + why);
        return warnings;
    }
    std::stable_sort(lossy.begin(), lossy.end(), [&](std::size_t a, std::size_t b) { return shares[a] > shares[b]; });
    std::string most;
    for (std::size_t k = 0; k < kListed; ++k) most += (k ? ", '" : "'") + names[lossy[k]] + "' " + percent(lossy[k]);
    warnings.push_back(std::to_string(lossy.size()) + " surfaces lose more than 0.1 % of their rays on the back of a "
                       "single-sided face" + what + ", the most " + most + why);
    return warnings;
}

}  // namespace rad
