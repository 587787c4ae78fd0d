#include "light/emitter.h"

#include <algorithm>

#include "mesh/elements.h"

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

glm::dvec3 DirectLight::total() const {
    glm::dvec3 sum = escaped + absorbedByBacks;
    for (const glm::dvec3& a : arrived) sum += a;
    return sum;
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

DirectLight Emitters::directLight(const PreparedScene& scene, const ElementMesh& elements, std::uint32_t seed,
                                  SpecularModel model) const {
    DirectLight light;
    for (const auto& e : list_) {
        if (!e->deliversDirectLight()) continue;
        if (light.empty()) light.arrived.assign(elements.elements().size(), glm::dvec3(0.0));
        e->addDirectLight(scene, elements, seed, model, light);
    }
    return light;
}

}  // namespace rad
