#pragma once
// The light from outside the scene: the radiance L(w) arriving from every direction w a ray
// leaves the scene in, either an environment map (--environment FILE.exr,
// scene/environment_map.h) or, as a constant environment, a uniform sky (--sky R,G,B: L the
// same from every direction). It is not a surface: its direct light is delivered to every
// element (kernels/direct_light.cl, environment_direct: for a map, rays half cosine-distributed
// and half drawn from the map, combined by multiple importance sampling, so a small bright sun is
// found as surely as the wide sky; for the constant sky, cosine-distributed rays, the irradiance
// pi L times the fraction that leaves the scene), and the solvers shoot what the elements
// reflect. Its power is what enters the scene's bounding sphere: pi R^2 times the integral of L
// over all directions (pi L x 4 pi R^2 for the sky); what reaches no element leaves again and
// counts as escaped. A map, where there is one, takes the sky's place.

#include <memory>

#include "light/emitter.h"
#include "scene/environment_map.h"
#include "scene/scene.h"

namespace rad {

class EnvironmentLight : public Emitter {
public:
    // The scene's map, else its sky; null when it has neither (Scene::sky black).
    static std::unique_ptr<EnvironmentLight> find(const Scene& scene);

    std::string describe() const override;
    glm::dvec3 power() const override;
    // A map: a direction drawn from the map (u.x, u.y) and a uniform point of the bounding
    // sphere's disk facing it (u.z, u.w); the light travels along -direction into the scene. The
    // sky: a uniform point of the bounding sphere (u.x, u.y) and a cosine-distributed direction
    // into it (u.z, u.w).
    EmissionSample sample(const glm::dvec4& u) const override;
    // The integral of L(w) cos over the hemisphere about `normal`: pi L for the sky; for a map,
    // of the filtered map, by the midpoint rule over 2 x 2 cells per texel.
    glm::dvec3 irradiance(const glm::dvec3& point, const glm::dvec3& normal) const override;
    DirectDelivery delivery() const override { return DirectDelivery::environment; }

private:
    std::shared_ptr<const EnvironmentMap> map_;  // null: the constant sky
    EnvironmentSampling sampling_;
    glm::dvec3 sky_{0.0};       // the constant radiance, W / m^2 / sr per channel, where no map
    glm::dvec3 integral_{0.0};  // a map's: the integral of L over the sphere, W / m^2 per channel
    glm::dvec3 centre_{0.0};
    double radius_ = 0.0;
};

}  // namespace rad
