#include "light/emitter.h"

#include <algorithm>


namespace rad {

CdfPick pickByCdf(const std::vector<double>& cdf, double u) {
    CdfPick pick;
    if (cdf.empty()) return pick;
    const double x = u * cdf.back();
    pick.index = std::min<std::size_t>(
        static_cast<std::size_t>(std::upper_bound(cdf.begin(), cdf.end(), x) - cdf.begin()), cdf.size() - 1);
    pick.start = pick.index == 0 ? 0.0 : cdf[pick.index - 1];
    pick.share = cdf[pick.index] - pick.start;
    return pick;
}

glm::dvec3 Emitters::power() const {
    glm::dvec3 sum(0.0);
    for (const auto& e : list_) sum += e->power();
    return sum;
}

std::vector<DirectSource> Emitters::directSources() const {
    std::vector<DirectSource> sources;
    for (const auto& e : list_) e->addDirectSources(sources);
    return sources;
}

PunctualLightSet Emitters::punctualLights() const {
    std::vector<PunctualLight> lights;
    for (const auto& e : list_) e->addPunctualLights(lights);
    return buildLightSet(lights);
}

}  // namespace rad
