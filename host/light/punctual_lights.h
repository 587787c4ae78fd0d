#pragma once
// The scene's punctual lights (KHR_lights_punctual: point, spot, directional) as one emitter.
// They are not surfaces, so nothing shoots them: their direct light is delivered to every
// element without noise (kernels/direct_light.cl: the closed-form irradiance at n * n points per
// element, each through a shadow ray), and the solvers shoot what the elements reflect.
//
// Power: a point light emits 4 pi I; a spot light 2 pi I (s^2 (x1 - cos_o)^3 / 3 + 1 - x1),
// x1 = min(1, cos_o + 1 / s), the integral of its smooth cone (s: the cone's scale,
// punctual_light.h; 1 - cos_o - 2 / (3 s) unless the cone is narrower than 1 / s); a directional light E_perp times
// the cross-section of the scene's bounding sphere, all that can reach the scene.

#include <memory>
#include <vector>

#include "light/emitter.h"
#include "scene/scene.h"

namespace rad {

class PunctualLights : public Emitter {
public:
    // The scene's lights; null when it has none.
    static std::unique_ptr<PunctualLights> find(const Scene& scene);

    std::string describe() const override;
    glm::dvec3 power() const override { return power_; }
    EmissionSample sample(const glm::dvec4& u) const override;
    glm::dvec3 irradiance(const glm::dvec3& point, const glm::dvec3& normal) const override;
    DirectDelivery delivery() const override { return DirectDelivery::punctual; }

    void addPunctualLights(std::vector<PunctualLight>& lights) const override {
        lights.insert(lights.end(), device_.begin(), device_.end());
    }

private:
    struct Placed {
        Light light;
        double cosOuter = 0.0, scale = 1.0, offset = 0.0;  // spot: attenuation clamp(cd * scale + offset)^2
        glm::dvec3 power{0.0};
    };
    std::vector<Placed> lights_;
    std::vector<PunctualLight> device_;
    std::vector<double> cdf_;  // sampling: running share of the power (summed over channels)
    glm::dvec3 power_{0.0};
    glm::dvec3 centre_{0.0};  // the scene's bounding sphere, which directional light enters
    double radius_ = 0.0;
};

}  // namespace rad
