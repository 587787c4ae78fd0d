#include "light/emissive_surfaces.h"

#include <algorithm>
#include <cmath>
#include <set>

#include <glm/geometric.hpp>

#include "util/analytic_form_factors.h"
#include "shared_math.h"

namespace rad {

std::unique_ptr<EmissiveSurfaces> EmissiveSurfaces::find(const Scene& scene, const Mesh& mesh,
                                                         const PatchTextureMeans& textures) {
    auto emitter = std::make_unique<EmissiveSurfaces>();
    double running = 0.0;
    for (std::uint32_t p = 0; p < mesh.patches.size(); ++p) {
        const Patch& patch = mesh.patches[p];
        const Material& material = scene.materials[static_cast<std::size_t>(patch.material)];
        const glm::vec3 radiance = material.emission * textures.emission[p];
        if (!(radiance.x > 0.0f || radiance.y > 0.0f || radiance.z > 0.0f)) continue;
        EmittingPatch e;
        e.patch = p;
        e.surface = patch.surface;
        for (int k = 0; k < 3; ++k)
            e.corners[static_cast<std::size_t>(k)] = glm::dvec3(patch.p[static_cast<std::size_t>(k)]);
        e.normal = glm::dvec3(patch.normal);
        e.radiance = radiance;
        e.area = patch.area;
        // In patch order, as every sum over the emitted power is taken.
        const glm::dvec3 power = kPi * patch.area * glm::dvec3(radiance);
        emitter->power_ += power;
        running += power.x + power.y + power.z;
        emitter->cdf_.push_back(running);
        emitter->patches_.push_back(e);
    }
    if (emitter->patches_.empty()) return nullptr;
    return emitter;
}

std::string EmissiveSurfaces::describe() const {
    std::set<std::uint32_t> surfaces;
    for (const EmittingPatch& e : patches_) surfaces.insert(e.surface);
    return std::to_string(surfaces.size()) + " emitting surface" + (surfaces.size() == 1 ? "" : "s") + " (" +
           std::to_string(patches_.size()) + " patch" + (patches_.size() == 1 ? "" : "es") + ")";
}

EmissionSample EmissiveSurfaces::sample(const glm::dvec4& u) const {
    EmissionSample s;
    const double total = cdf_.empty() ? 0.0 : cdf_.back();
    if (!(total > 0.0)) return s;
    // The patch by its share of the power; u.x, rescaled within that share, then picks the point.
    const double x = u.x * total;
    const CdfPick pick = pickByCdf(cdf_, u.x);
    const std::size_t k = pick.index;
    const double start = pick.start;
    const double share = pick.share;  // 0 only where rounding put x at the very end, on a patch of no area
    const double reused = share > 0.0 ? std::clamp((x - start) / share, 0.0, 1.0) : 0.5;
    const EmittingPatch& e = patches_[k];
    // A uniform point of the triangle, and a cosine-distributed direction about its normal.
    const double r = std::sqrt(reused);
    const double b1 = r * (1.0 - u.y), b2 = r * u.y;
    s.position = e.corners[0] + b1 * (e.corners[1] - e.corners[0]) + b2 * (e.corners[2] - e.corners[0]);
    s.normal = e.normal;
    const glm::dvec3 tangent = glm::normalize(e.corners[1] - e.corners[0]);
    const glm::dvec3 bitangent = glm::cross(e.normal, tangent);
    const double radius = std::sqrt(u.z), phi = 2.0 * kPi * u.w;
    s.direction = radius * std::cos(phi) * tangent + radius * std::sin(phi) * bitangent +
                  std::sqrt(std::max(0.0, 1.0 - u.z)) * e.normal;
    // Probability of this patch: share / total; the point and direction carry the patch's power.
    s.power = kPi * static_cast<double>(e.area) * glm::dvec3(e.radiance) * (total / share);
    return s;
}

glm::dvec3 EmissiveSurfaces::irradiance(const glm::dvec3& point, const glm::dvec3& normal) const {
    glm::dvec3 sum(0.0);
    for (const EmittingPatch& e : patches_) {
        if (glm::dot(e.normal, point - e.corners[0]) <= 0.0) continue;  // behind the emitting side
        // The part of the patch above the point's horizon (as kernels/polygon_factor.h clips it).
        std::vector<glm::dvec3> polygon;
        for (std::size_t k = 0; k < 3; ++k) {
            const glm::dvec3 a = e.corners[k], b = e.corners[(k + 1) % 3];
            const double da = glm::dot(normal, a - point), db = glm::dot(normal, b - point);
            if (da > 0.0) polygon.push_back(a);
            if ((da > 0.0) != (db > 0.0)) polygon.push_back(a + (da / (da - db)) * (b - a));
        }
        if (polygon.size() < 3) continue;
        sum += kPi * glm::dvec3(e.radiance) * pointToPolygonFactor(point, normal, polygon);
    }
    return sum;
}

void EmissiveSurfaces::addPatchEmission(std::vector<glm::vec3>& radiance) const {
    for (const EmittingPatch& e : patches_) radiance[e.patch] += e.radiance;
}

void EmissiveSurfaces::addDirectSources(std::vector<DirectSource>& sources) const {
    for (const EmittingPatch& e : patches_) sources.push_back({e.patch, e.radiance, static_cast<double>(e.area)});
}

}  // namespace rad
