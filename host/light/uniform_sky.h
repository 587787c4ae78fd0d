#pragma once
// A sky of uniform radiance L (--sky R,G,B) around the scene: every direction a ray leaves the
// scene in sees L. It is not a surface, so its direct light is delivered to every element
// (kernels/direct_light.cl: cosine-distributed rays from stratified points of the element; the
// irradiance is pi L times the fraction that leaves the scene), and the solvers shoot what the
// elements reflect. The sky's power is what enters the scene's bounding sphere, pi L x 4 pi R^2;
// what reaches no element leaves again and counts as escaped.

#include <memory>

#include "light/emitter.h"
#include "scene/scene.h"

namespace rad {

class UniformSky : public Emitter {
public:
    // The scene's sky; null when it has none (Scene::sky is black).
    static std::unique_ptr<UniformSky> find(const Scene& scene);

    std::string describe() const override;
    glm::dvec3 power() const override;
    EmissionSample sample(const glm::dvec4& u) const override;
    glm::dvec3 irradiance(const glm::dvec3& point, const glm::dvec3& normal) const override;
    DirectDelivery delivery() const override { return DirectDelivery::environment; }

private:
    glm::dvec3 radiance_{0.0};
    glm::dvec3 centre_{0.0};
    double radius_ = 0.0;
};

}  // namespace rad
