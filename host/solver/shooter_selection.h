#pragma once
// Choosing a batch of shooters from the gather kernel's partial reductions, and the rays and
// per-ray power of each. Pure functions of their inputs, so every run makes the same choices.

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "shared_types.h"

namespace rad {

struct Candidate {
    std::uint32_t cluster = 0;  // mesh/patch_clusters.h: a patch of its own where none is small
    glm::vec3 power{0.0f};  // power to shoot per channel (negative: owed), device units
    float total = 0.0f;     // its magnitude, |r| + |g| + |b|
};

// The partials' largest clusters, strongest first (ties: lower cluster index first); at most
// maxCount, none weaker than ratio x the strongest, none without power.
std::vector<Candidate> selectShooters(const std::vector<UnshotPartial>& partials, std::uint32_t maxCount,
                                      double ratio);

// Rays for a shot of `total` W when a shot of all the emitted power gets `rays`:
// clamp(rays * total / emitted, minRays, 2^31).
std::uint32_t raysForShot(double total, double emitted, std::uint64_t rays, std::uint32_t minRays);

// A cluster's `rays` shared among its patches in proportion to their power to shoot
// (`magnitudes`, |r| + |g| + |b|): at least one for each that has any, none for the others (which
// keep what they owe), so every ray carries about the same power.
std::vector<std::uint32_t> shareRays(const std::vector<double>& magnitudes, std::uint32_t rays);

// The shooter's fixed-point per-ray weights (kernels/shared_types.h: Shooter) for `rays` rays
// carrying `power` in quanta of `quantum` W, rounded towards zero so a shot never moves more
// than the shooter has (a negative channel: what it owes); `taken` is what the rays carry in all.
Shooter makeShooter(std::uint32_t patch, const glm::vec3& power, std::uint32_t rays, float quantum);

}  // namespace rad
