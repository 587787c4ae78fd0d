#include "light/punctual_lights.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "punctual_light.h"
#include "shared_math.h"

namespace rad {

namespace {

double luminance(const glm::dvec3& c) {
    return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
}

// An orthonormal pair perpendicular to the unit vector n.
void perpendicular(const glm::dvec3& n, glm::dvec3& t, glm::dvec3& b) {
    t = glm::normalize(std::fabs(n.x) > 0.5 ? glm::cross(n, glm::dvec3(0, 1, 0)) : glm::cross(n, glm::dvec3(1, 0, 0)));
    b = glm::cross(n, t);
}

}  // namespace

std::unique_ptr<PunctualLights> PunctualLights::find(const Scene& scene) {
    if (scene.lights.empty()) return nullptr;
    auto emitter = std::make_unique<PunctualLights>();
    const Bounds bounds = scene.bounds();
    emitter->centre_ = bounds.centre();
    emitter->radius_ = bounds.radius();
    double running = 0.0;
    for (const Light& light : scene.lights) {
        Placed p;
        p.light = light;
        switch (light.type) {
            case Light::Type::Point:
                p.power = 4.0 * kPi * light.intensity;
                break;
            case Light::Type::Spot: {
                // glTF's recommended cone: scale = 1 / max(0.001, cos_i - cos_o), offset = -cos_o scale.
                p.cosOuter = std::cos(light.outerConeAngle);
                p.scale = 1.0 / std::max(0.001, std::cos(light.innerConeAngle) - p.cosOuter);
                p.offset = -p.cosOuter * p.scale;
                // The ramp clamp((cd - cos_o) s, 0, 1)^2 rises from cos_o to x1 = min(1, cos_o + 1/s)
                // (a cone narrower than 1/s never reaches full strength); full strength beyond.
                const double x1 = std::min(1.0, p.cosOuter + 1.0 / p.scale);
                const double ramp = x1 - p.cosOuter;
                p.power = 2.0 * kPi * (p.scale * p.scale * ramp * ramp * ramp / 3.0 + (1.0 - x1)) * light.intensity;
                break;
            }
            case Light::Type::Directional:
                p.power = kPi * emitter->radius_ * emitter->radius_ * light.intensity;
                break;
        }
        emitter->power_ += p.power;
        running += p.power.x + p.power.y + p.power.z;
        emitter->cdf_.push_back(running);

        PunctualLight d{};
        for (int c = 0; c < 3; ++c) {
            d.position[c] = static_cast<float>(light.position[c]);
            d.direction[c] = static_cast<float>(light.direction[c]);
            d.intensity[c] = static_cast<float>(light.intensity[c]);
        }
        d.intensity[3] = static_cast<float>(luminance(light.intensity));
        d.cone[0] = static_cast<float>(p.scale);
        d.cone[1] = static_cast<float>(p.offset);
        d.type = light.type == Light::Type::Point  ? RAD_LIGHT_POINT
                 : light.type == Light::Type::Spot ? RAD_LIGHT_SPOT
                                                   : RAD_LIGHT_DIRECTIONAL;
        emitter->device_.push_back(d);
        emitter->lights_.push_back(p);
    }
    return emitter;
}

std::string PunctualLights::describe() const {
    std::size_t count[3] = {0, 0, 0};
    for (const Placed& p : lights_) ++count[static_cast<int>(p.light.type)];
    const char* names[3] = {"point", "spot", "directional"};
    std::string text;
    for (int k = 0; k < 3; ++k) {
        if (count[k] == 0) continue;
        text += (text.empty() ? "" : ", ") + std::to_string(count[k]) + " " + names[k] + " light" +
                (count[k] == 1 ? "" : "s");
    }
    return text;
}

EmissionSample PunctualLights::sample(const glm::dvec4& u) const {
    EmissionSample s;
    const double total = cdf_.empty() ? 0.0 : cdf_.back();
    if (!(total > 0.0)) return s;
    const CdfPick pick = pickByCdf(cdf_, u.x);
    const std::size_t k = pick.index;
    const double share = pick.share;
    if (!(share > 0.0)) return s;
    const Placed& p = lights_[k];
    const double phi = 2.0 * kPi * u.z;
    switch (p.light.type) {
        case Light::Type::Point: {  // a uniform direction
            const double z = 1.0 - 2.0 * u.y, r = std::sqrt(std::max(0.0, 1.0 - z * z));
            s.position = p.light.position;
            s.direction = glm::dvec3(r * std::cos(phi), r * std::sin(phi), z);
            s.power = p.power * (total / share);
            break;
        }
        case Light::Type::Spot: {  // a uniform direction within the outer cone, weighted by the attenuation
            const double cd = 1.0 - u.y * (1.0 - p.cosOuter), r = std::sqrt(std::max(0.0, 1.0 - cd * cd));
            glm::dvec3 t, b;
            perpendicular(p.light.direction, t, b);
            s.position = p.light.position;
            s.direction = r * std::cos(phi) * t + r * std::sin(phi) * b + cd * p.light.direction;
            const double solidAngle = 2.0 * kPi * (1.0 - p.cosOuter);
            s.power = (rad_spot_attenuation(cd, p.scale, p.offset) * solidAngle) * p.light.intensity * (total / share);
            break;
        }
        case Light::Type::Directional: {  // a uniform point of the bounding sphere's cross-section
            glm::dvec3 t, b;
            perpendicular(p.light.direction, t, b);
            const double r = radius_ * std::sqrt(u.y);
            s.position = centre_ - radius_ * p.light.direction + r * std::cos(phi) * t + r * std::sin(phi) * b;
            s.direction = p.light.direction;
            s.power = p.power * (total / share);
            break;
        }
    }
    s.normal = s.direction;
    return s;
}

glm::dvec3 PunctualLights::irradiance(const glm::dvec3& point, const glm::dvec3& normal) const {
    glm::dvec3 sum(0.0);
    for (const Placed& p : lights_) {
        if (p.light.type == Light::Type::Directional) {
            sum += std::max(0.0, -glm::dot(normal, p.light.direction)) * p.light.intensity;
            continue;
        }
        const glm::dvec3 d = p.light.position - point;
        const double r2 = glm::dot(d, d);
        if (!(r2 > 0.0)) continue;
        const glm::dvec3 toLight = d / std::sqrt(r2);
        const double c = glm::dot(normal, toLight);
        if (!(c > 0.0)) continue;
        const double attenuation = p.light.type == Light::Type::Spot
                                       ? rad_spot_attenuation(-glm::dot(p.light.direction, toLight), p.scale, p.offset)
                                       : 1.0;
        sum += (attenuation * c / r2) * p.light.intensity;
    }
    return sum;
}

}  // namespace rad
