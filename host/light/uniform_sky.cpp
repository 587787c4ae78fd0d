#include "light/uniform_sky.h"

#include <cmath>
#include <cstdio>

#include <glm/geometric.hpp>

#include "shared_math.h"
#include "util/sample_streams.h"

namespace rad {

std::unique_ptr<UniformSky> UniformSky::find(const Scene& scene) {
    // One light from outside: a map where there is one (environment_light.h), else the sky.
    if (scene.environment || !(scene.sky.x > 0.0f || scene.sky.y > 0.0f || scene.sky.z > 0.0f)) return nullptr;
    auto sky = std::make_unique<UniformSky>();
    sky->radiance_ = glm::dvec3(scene.sky);
    const Bounds bounds = scene.bounds();
    sky->centre_ = bounds.centre();
    sky->radius_ = bounds.radius();
    return sky;
}

std::string UniformSky::describe() const {
    char text[96];
    std::snprintf(text, sizeof text, "a uniform sky (%g, %g, %g W/m^2/sr)", radiance_.x, radiance_.y, radiance_.z);
    return text;
}

glm::dvec3 UniformSky::power() const {
    return kPi * radiance_ * (4.0 * kPi * radius_ * radius_);
}

EmissionSample UniformSky::sample(const glm::dvec4& u) const {
    // A uniform point of the bounding sphere, and a cosine-distributed direction into it.
    EmissionSample s;
    const double z = 1.0 - 2.0 * u.x, r = std::sqrt(std::max(0.0, 1.0 - z * z)), phi = 2.0 * kPi * u.y;
    const glm::dvec3 outward(r * std::cos(phi), r * std::sin(phi), z);
    s.position = centre_ + radius_ * outward;
    s.normal = -outward;
    const glm::dvec3 t = glm::normalize(std::fabs(s.normal.x) > 0.5 ? glm::cross(s.normal, glm::dvec3(0, 1, 0))
                                                                    : glm::cross(s.normal, glm::dvec3(1, 0, 0)));
    const glm::dvec3 b = glm::cross(s.normal, t);
    const double radius = std::sqrt(u.z), angle = 2.0 * kPi * u.w;
    s.direction =
        radius * std::cos(angle) * t + radius * std::sin(angle) * b + std::sqrt(std::max(0.0, 1.0 - u.z)) * s.normal;
    s.power = power();
    return s;
}

glm::dvec3 UniformSky::irradiance(const glm::dvec3&, const glm::dvec3&) const {
    return kPi * radiance_;
}

}  // namespace rad
