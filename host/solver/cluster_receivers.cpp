#include "solver/cluster_receivers.h"

#include <cmath>

namespace rad {
namespace {

double hitsOf(const glm::dvec3& power, double rayPower) {
    return std::max(0.0, power.x + power.y + power.z) / rayPower;
}

}  // namespace

PooledReceivers poolReceivers(const ElementMesh& elements, const PatchClusters& clusters,
                              const std::vector<glm::dvec3>& shot, double rayPower) {
    PooledReceivers out;
    out.power = shot;
    out.hits.resize(shot.size());
    if (!(rayPower > 0.0)) return out;
    for (std::size_t e = 0; e < shot.size(); ++e) out.hits[e] = hitsOf(shot[e], rayPower);
    const std::vector<Element>& list = elements.elements();
    const std::vector<std::uint32_t>& start = elements.elementStart();
    std::vector<std::uint32_t> members;  // the cluster's elements
    std::vector<bool> agrees;
    for (std::size_t c = 0; c < clusters.count(); ++c) {
        if (clusters.size(c) < 2) continue;
        members.clear();
        for (std::uint32_t m = clusters.start()[c]; m < clusters.start()[c + 1]; ++m)
            for (std::uint32_t e = start[clusters.members()[m]]; e < start[clusters.members()[m] + 1]; ++e)
                members.push_back(e);
        double hits = 0.0, area = 0.0;
        for (const std::uint32_t e : members) {
            hits += out.hits[e];
            area += list[e].area;
        }
        if (!(area > 0.0)) continue;
        // Which elements' hits agree with the cluster's density; then the density of those alone.
        agrees.assign(members.size(), false);
        glm::dvec3 power(0.0);
        double poolHits = 0.0, poolArea = 0.0;
        std::size_t agreeing = 0;
        for (std::size_t i = 0; i < members.size(); ++i) {
            const std::uint32_t e = members[i];
            const double expected = hits / area * list[e].area;
            agrees[i] = std::fabs(out.hits[e] - expected) <= 3.0 * std::sqrt(expected) + 1.0;
            if (!agrees[i]) continue;
            power += shot[e];
            poolHits += out.hits[e];
            poolArea += list[e].area;
            ++agreeing;
        }
        // A pool of one is the element's own value, bit for bit.
        if (agreeing < 2 || !(poolArea > 0.0) || !(poolHits > 0.0)) continue;
        // How much the light really varies among them, beyond their Poisson noise: the relative
        // variance v of their true densities (empirical Bayes; Poisson counts k_i with means
        // m_i = K A_i / A have E[(k_i - m_i)^2] = m_i + v m_i^2). Each keeps the share
        // lambda_i = v m_i / (v m_i + 1) of its own value and takes the rest from the pool: all
        // of the pool where the light is even (v = 0), more and more of its own where the light
        // varies by more than its noise shows, or as its hits grow.
        double excess = 0.0, squares = 0.0;
        for (std::size_t i = 0; i < members.size(); ++i) {
            if (!agrees[i]) continue;
            const double m = poolHits * list[members[i]].area / poolArea;
            excess += (out.hits[members[i]] - m) * (out.hits[members[i]] - m) - m;
            squares += m * m;
        }
        const double v = squares > 0.0 ? std::max(0.0, excess / squares) : 0.0;
        glm::dvec3 sum(0.0);
        for (std::size_t i = 0; i < members.size(); ++i) {
            if (!agrees[i]) continue;
            const std::uint32_t e = members[i];
            const double m = poolHits * list[e].area / poolArea;
            const double own = v * m / (v * m + 1.0);
            out.power[e] = (1.0 - own) * power * (static_cast<double>(list[e].area) / poolArea) + own * shot[e];
            sum += out.power[e];
            // 1 / its relative mean squared error: the own part's Poisson noise and the pool's,
            // and the bias of taking the pool's density where the element's own differs by the
            // spread v shows (own^2 / m + (1 - own)^2 v with own = v m / (v m + 1) is own / m).
            const double noise = (m > 0.0 ? own / m : 0.0) + (1.0 - own) * (1.0 - own) / poolHits;
            out.hits[e] = noise > 0.0 ? 1.0 / noise : poolHits;
            if (own < 0.5) ++out.pooled;
        }
        // The shares need not add to one where areas differ: keep the pool's power, per channel.
        for (std::size_t i = 0; i < members.size(); ++i) {
            if (!agrees[i]) continue;
            for (int c = 0; c < 3; ++c)
                if (sum[c] > 0.0) out.power[members[i]][c] *= power[c] / sum[c];
        }
    }
    return out;
}

}  // namespace rad
