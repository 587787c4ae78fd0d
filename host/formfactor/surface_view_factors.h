#pragma once
// Surface-to-surface view factors by ray shooting. Each surface side casts the same number of
// rays, spread over its patches in proportion to area (stratified by the area table), so a
// small surface gets as precise a row as a large one. F_ST = (rays from S landing on T) / N is
// the area-weighted mean of the patch rows F_pT.

#include <cstdint>
#include <string>
#include <vector>

#include "parallel/process_group.h"
#include "prepared/prepared_scene.h"

namespace rad {

struct ViewFactorOptions {
    std::uint64_t raysPerSurface = 1'000'000;
    std::uint32_t seed = 1;
    // This process's share when several divide the rows (parallel/ranks.h): it shoots only
    // from the surfaces s with s mod ranks == rank, and leaves the other rows empty. A row's
    // rays depend only on the seed and the surface, so the rows are those of one process.
    std::uint32_t rank = 0, ranks = 1;
};

struct SurfaceViewFactors {
    std::vector<std::string> names;
    std::vector<double> areas;                 // m^2
    std::uint64_t raysPerSurface = 0;
    // rows[from]: (to, rays that landed on it) for every surface it hit, in surface order.
    // Sparse, so memory grows with what is hit, not with the square of the surface count.
    std::vector<std::vector<std::pair<std::uint32_t, std::uint64_t>>> rows;
    std::vector<std::uint64_t> escaped;        // rays that left the scene, per source surface
    std::vector<std::uint64_t> blackBack;      // rays stopped by a single-sided face's back
    // Where computeSurfaceViewFactors spent its time, seconds (bench/embree_compare's whole
    // job): the rays cast and counted on the device, to the end of its queue; the counts read
    // back; the patches' counts added up per surface.
    struct Seconds {
        double shooting = 0.0, reading = 0.0, adding = 0.0;
    } seconds;

    std::size_t size() const { return names.size(); }
    std::uint64_t hits(std::size_t from, std::size_t to) const;
    double factor(std::size_t from, std::size_t to) const;
    // Standard error of factor(): sqrt(F (1 - F) / N), that of independent rays. Stratified
    // rays do better, so this is an upper bound on the estimator's actual error.
    double standardError(std::size_t from, std::size_t to) const;
};

SurfaceViewFactors computeSurfaceViewFactors(const PreparedScene& scene, const ViewFactorOptions& options);

// The same with the surfaces divided among `group`'s processes (options' rank and ranks are
// set from it) and the rows gathered: every process holds the whole result, bitwise one
// process's.
SurfaceViewFactors computeSurfaceViewFactors(const PreparedScene& scene, ViewFactorOptions options,
                                             const ProcessGroup& group);

// The rows a process computed (those of surfaces s with s mod ranks == rank) as numbers, and
// the rows of every process put back together from all of theirs concatenated.
std::vector<std::uint64_t> packOwnRows(const SurfaceViewFactors& factors, std::uint32_t rank, std::uint32_t ranks);
void unpackRows(SurfaceViewFactors& factors, const std::vector<std::uint64_t>& packed);

// Independent estimates of one scene's factors, added up: the factors of all their rays.
SurfaceViewFactors poolSurfaceViewFactors(const std::vector<SurfaceViewFactors>& parts);

// Rays added until every factor's standard error (the binomial bound, standardError()) is at
// most `targetError`, or `maxRays` per surface are spent. Each round casts what the factors
// found so far say is still needed (F (1 - F) / E^2 in all, at least `firstRays` the first
// time), with its own seed, and pools it with the rounds before. Every surface takes the same
// rays: the row that needs the most decides.
struct TargetErrorEstimate {
    SurfaceViewFactors factors;
    int rounds = 0;
    double largestError = 0.0;  // the largest standard error reached
    bool reached = false;
};
TargetErrorEstimate computeSurfaceViewFactorsToError(const PreparedScene& scene, double targetError, std::uint32_t seed,
                                                     std::uint64_t firstRays, std::uint64_t maxRays,
                                                     const ProcessGroup& group = oneProcess());

// The warnings for rays stopped on the black backs of single-sided faces: one line per surface
// that lost more than 0.1 % of its rays there when at most three did, otherwise one line with how
// many and the three largest. `consequence` says what the command made of those rays.
std::vector<std::string> blackBackWarnings(const std::vector<std::string>& names, const std::vector<double>& shares,
                                           const std::string& consequence);

}  // namespace rad
