#include "solver/ray_hit_checks.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "prepared/patch_system.h"
#include "shared_math.h"
#include "util/format.h"

namespace rad {

std::vector<std::string> rayHitWarnings(const PreparedScene& scene, const ElementMesh& elements,
                                        const std::vector<glm::vec3>& radiosity, std::uint64_t rays,
                                        double rayPowerScale) {
    const Mesh& mesh = scene.mesh();
    const PatchSystem& patches = scene.patches();
    // Every ray carries about the emitted power over `rays`, in each channel (weaker shots
    // cast at least --min-rays, whose rays carry less, so this undercounts hits, if anything).
    // Receiver j (an element) received A_j (B_j - E_j) / rho_j per channel; in rays, that over
    // the power a ray carries in the same channels (black channels say nothing and are left
    // out of both).
    const glm::dvec3 emitted = scene.emitters().power();
    const std::vector<Element>& receivers = elements.elements();
    if (!(emitted.x + emitted.y + emitted.z > 0.0) || rays == 0 || radiosity.size() != receivers.size()) return {};
    // The reflectance the solve used: mirrors and glass reflect nothing diffusely in it (their
    // light goes on through them: prepared/patch_system.h's reflectanceBesideSpecular), so say
    // nothing of their hits.
    const std::vector<glm::vec3> reflectance =
        scene.device().specularFaces() ? reflectanceBesideSpecular(patches, scene.scene(), mesh) : patches.reflectance;
    std::vector<double> hits;
    std::size_t none = 0;
    for (std::size_t j = 0; j < receivers.size(); ++j) {
        const glm::vec3 rho = reflectance[receivers[j].patch], le = patches.emission[receivers[j].patch];
        double received = 0.0, perRay = 0.0;
        for (int c = 0; c < 3; ++c) {
            if (!(rho[c] > 0.01f)) continue;
            const double b = radiosity[j][c], e = kPi * le[c];
            received += std::max(0.0, b - e) / rho[c];
            perRay += emitted[c] / static_cast<double>(rays) * rayPowerScale;
        }
        if (!(perRay > 0.0)) continue;  // black, or lit in no channel it reflects
        const double k = received * receivers[j].area / perRay;
        hits.push_back(k);
        if (!(k > 0.0)) ++none;
    }
    if (hits.empty()) return {};
    std::sort(hits.begin(), hits.end());
    const double median = hits[hits.size() / 2];
    // Fewer than 25 hits for the median receiver is 20 % noise, and many get none. (The tail is
    // no guide: a receiver that only weak shots reach looks sparse even when it is not, and some
    // are out of every light's reach.)
    if (median >= 25.0) return {};
    const bool split = receivers.size() > mesh.patches.size();
    const char* unit = split ? "element" : "patch";
    const char* units = split ? "elements" : "patches";
    const double needed = std::ceil(static_cast<double>(rays) * 100.0 / std::max(median, 0.1));
    const std::string effect = median > 0.0 ? format(
                                                  "%s values carry about %.0f %% noise and small receivers may get "
                                                  "no hit at all",
                                                  unit, 100.0 / std::sqrt(median))
                                            : format("most %s got no light at all", units);
    return {
        format("shoot: the median %s's radiosity rests on about %.3g ray hits (%zu of %zu reflecting %s got "
               "none), so %s; use --rays %.3g or more (now %llu) for about 100 hits per %s, or a larger %s",
               unit, median, none, hits.size(), units, effect.c_str(), needed, static_cast<unsigned long long>(rays),
               unit, split ? "--element-size (or fewer refinements)" : "--patch-size")};
}

}  // namespace rad
