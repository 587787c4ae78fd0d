#include "solver/shooter_selection.h"

#include <algorithm>
#include <cmath>

namespace rad {

std::vector<Candidate> selectShooters(const std::vector<UnshotPartial>& partials, std::uint32_t maxCount,
                                      double ratio) {
    std::vector<Candidate> candidates;
    for (const UnshotPartial& p : partials)
        if (p.largest[3] > 0.0f)
            candidates.push_back({p.largestCluster, glm::vec3(p.largest[0], p.largest[1], p.largest[2]), p.largest[3]});
    std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
        return a.total > b.total || (a.total == b.total && a.cluster < b.cluster);
    });
    if (candidates.size() > maxCount) candidates.resize(maxCount);
    if (!candidates.empty()) {
        const double floor = ratio * candidates.front().total;
        candidates.erase(std::find_if(candidates.begin(), candidates.end(),
                                      [&](const Candidate& c) { return c.total < floor; }),
                         candidates.end());
    }
    return candidates;
}

std::uint32_t raysForShot(double total, double emitted, std::uint64_t rays, std::uint32_t minRays) {
    const double wanted = emitted > 0.0 ? std::round(static_cast<double>(rays) * total / emitted) : 0.0;
    return static_cast<std::uint32_t>(std::clamp(wanted, static_cast<double>(minRays), 2147483648.0));
}

std::vector<std::uint32_t> shareRays(const std::vector<double>& magnitudes, std::uint32_t rays) {
    double total = 0.0;
    for (const double m : magnitudes) total += m > 0.0 ? m : 0.0;
    std::vector<std::uint32_t> shares(magnitudes.size(), 0);
    if (!(total > 0.0)) return shares;
    for (std::size_t i = 0; i < magnitudes.size(); ++i)
        if (magnitudes[i] > 0.0)
            shares[i] = static_cast<std::uint32_t>(
                std::clamp(std::round(static_cast<double>(rays) * magnitudes[i] / total), 1.0, 2147483648.0));
    return shares;
}

Shooter makeShooter(std::uint32_t patch, const glm::vec3& power, std::uint32_t rays, float quantum) {
    Shooter s{};
    s.patch = patch;
    s.rays = rays;
    for (int c = 0; c < 3; ++c) {
        // Rounded towards zero, so a shot never moves more than the shooter has, either way.
        const double perRay = static_cast<double>(power[c]) / rays / static_cast<double>(quantum);
        const auto units = static_cast<std::int64_t>(std::trunc(std::clamp(perRay, -9.2e18, 9.2e18)));
        const auto pattern = static_cast<std::uint64_t>(units);  // two's complement, as the kernels add it
        s.weight[2 * c] = static_cast<rad_uint>(pattern & 0xFFFFFFFFu);
        s.weight[2 * c + 1] = static_cast<rad_uint>(pattern >> 32);
        s.taken[c] = static_cast<float>(static_cast<double>(units) * rays * static_cast<double>(quantum));
    }
    s.taken[3] = 0.0f;
    return s;
}

}  // namespace rad
