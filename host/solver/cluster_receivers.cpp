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
        for (std::size_t i = 0; i < members.size(); ++i) {
            const std::uint32_t e = members[i];
            const double expected = hits / area * list[e].area;
            agrees[i] = std::fabs(out.hits[e] - expected) <= 3.0 * std::sqrt(expected) + 1.0;
            if (!agrees[i]) continue;
            power += shot[e];
            poolHits += out.hits[e];
            poolArea += list[e].area;
        }
        if (!(poolArea > 0.0)) continue;
        for (std::size_t i = 0; i < members.size(); ++i) {
            if (!agrees[i]) continue;
            const std::uint32_t e = members[i];
            out.power[e] = power * (static_cast<double>(list[e].area) / poolArea);
            out.hits[e] = poolHits;
            ++out.pooled;
        }
    }
    return out;
}

}  // namespace rad
