#pragma once
// An environment map around the scene (--environment FILE.exr, scene/environment_map.h): the
// radiance L(w) arriving from every direction w a ray leaves the scene in. Like the uniform
// sky it is not a surface: its direct light is delivered to every element
// (kernels/direct_light.cl, environment_direct: rays half cosine-distributed and half drawn
// from the map, combined by multiple importance sampling, so a small bright sun is found as
// surely as the wide sky), and the solvers shoot what the elements reflect. Its power is what
// enters the scene's bounding sphere: pi R^2 times the integral of L over all directions.

#include <memory>

#include "light/emitter.h"
#include "scene/environment_map.h"
#include "scene/scene.h"

namespace rad {

class EnvironmentLight : public Emitter {
public:
    // The scene's environment map; null when it has none.
    static std::unique_ptr<EnvironmentLight> find(const Scene& scene);

    std::string describe() const override;
    glm::dvec3 power() const override;
    // A direction drawn from the map (u.x, u.y) and a uniform point of the bounding sphere's
    // disk facing it (u.z, u.w); the light travels along -direction into the scene.
    EmissionSample sample(const glm::dvec4& u) const override;
    // The integral of the filtered L(w) cos over the hemisphere about `normal` (the midpoint rule
    // over 2 x 2 cells per texel).
    glm::dvec3 irradiance(const glm::dvec3& point, const glm::dvec3& normal) const override;
    DirectDelivery delivery() const override { return DirectDelivery::environment; }

private:
    std::shared_ptr<const EnvironmentMap> map_;
    EnvironmentSampling sampling_;
    glm::dvec3 integral_{0.0};  // the integral of L over the sphere, W / m^2 per channel
    glm::dvec3 centre_{0.0};
    double radius_ = 0.0;
};

}  // namespace rad
