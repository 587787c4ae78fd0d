#include "light/environment_light.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/geometric.hpp>

#include "shared_math.h"
#include "util/sample_streams.h"

namespace rad {
namespace {

// The share of `ends` (the last end, 2^32, implied) that u in [0, 1) falls in, and where in it.
std::size_t pickShare(const std::uint32_t* ends, std::size_t count, double u, double& within) {
    const double x = std::floor(u * 4294967296.0);
    // The first share whose end lies beyond x (the last one if none).
    const auto beyond =
        std::upper_bound(ends, ends + count - 1, x, [](double v, std::uint32_t end) { return v < end; });
    const auto k = static_cast<std::size_t>(beyond - ends);
    const double start = k == 0 ? 0.0 : ends[k - 1], end = k + 1 == count ? 4294967296.0 : ends[k];
    within = end > start ? std::min((x - start) / (end - start), 1.0) : 0.0;
    return k;
}

}  // namespace

std::unique_ptr<EnvironmentLight> EnvironmentLight::find(const Scene& scene) {
    const bool sky = scene.sky.x > 0.0f || scene.sky.y > 0.0f || scene.sky.z > 0.0f;
    if (!scene.environment && !sky) return nullptr;
    auto light = std::make_unique<EnvironmentLight>();
    if (scene.environment) {
        light->map_ = scene.environment;
        light->sampling_ = environmentSampling(*scene.environment);
        light->integral_ = environmentIntegral(*scene.environment);
    } else {
        light->sky_ = glm::dvec3(scene.sky);
    }
    const Bounds bounds = scene.bounds();
    light->centre_ = bounds.centre();
    light->radius_ = bounds.radius();
    return light;
}

std::string EnvironmentLight::describe() const {
    if (!map_) {
        char text[96];
        std::snprintf(text, sizeof text, "a uniform sky (%g, %g, %g W/m^2/sr)", sky_.x, sky_.y, sky_.z);
        return text;
    }
    char text[64];
    std::snprintf(text, sizeof text, " (%d x %d texels, strength %g)", map_->width, map_->height, map_->strength);
    return "the environment map " + map_->path + text;
}

glm::dvec3 EnvironmentLight::power() const {
    // The sky's as pi L x 4 pi R^2, in that order (the same power, to the bit, wherever it is asked).
    if (!map_) return kPi * sky_ * (4.0 * kPi * radius_ * radius_);
    return kPi * radius_ * radius_ * integral_;
}

EmissionSample EnvironmentLight::sample(const glm::dvec4& u) const {
    if (!map_) {
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
        s.direction = radius * std::cos(angle) * t + radius * std::sin(angle) * b +
                      std::sqrt(std::max(0.0, 1.0 - u.z)) * s.normal;
        s.power = power();
        return s;
    }
    const EnvironmentMap& map = *map_;
    double fy = 0.0, fx = 0.0;
    const std::size_t y = pickShare(sampling_.rows.data(), map.height, u.x, fy);
    const std::size_t x =
        pickShare(sampling_.columns.data() + y * static_cast<std::size_t>(map.width), map.width, u.y, fx);
    // Uniform in solid angle within the texel: cos(theta) uniform between its rows' edges.
    const double top = std::cos(kPi * y / map.height), bottom = std::cos(kPi * (y + 1.0) / map.height);
    const double cosTheta = top + fy * (bottom - top);
    const double t = std::acos(std::clamp(cosTheta, -1.0, 1.0)) / kPi;
    const glm::dvec3 toward = environmentDirection((x + fx) / map.width, t);
    const double pdf = environmentPdf(map, sampling_, toward);
    // A uniform point of the disk, facing `toward`, that the bounding sphere casts.
    const glm::dvec3 a = glm::normalize(std::fabs(toward.x) > 0.5 ? glm::cross(toward, glm::dvec3(0, 1, 0))
                                                                  : glm::cross(toward, glm::dvec3(1, 0, 0)));
    const glm::dvec3 b = glm::cross(toward, a);
    const double r = radius_ * std::sqrt(u.z), angle = 2.0 * kPi * u.w;
    EmissionSample s;
    s.position = centre_ + radius_ * toward + r * std::cos(angle) * a + r * std::sin(angle) * b;
    s.normal = -toward;
    s.direction = -toward;
    s.power = pdf > 0.0 ? environmentRadiance(map, toward) * (kPi * radius_ * radius_ / pdf) : glm::dvec3(0.0);
    return s;
}

glm::dvec3 EnvironmentLight::irradiance(const glm::dvec3&, const glm::dvec3& normal) const {
    if (!map_) return kPi * sky_;
    // The filtered map (as the kernels read it) times the cosine, by the midpoint rule over 2 x 2
    // cells per texel, each uniform in u and in cos(theta).
    const EnvironmentMap& map = *map_;
    constexpr int kSub = 2;
    glm::dvec3 sum(0.0);
    for (int y = 0; y < map.height * kSub; ++y) {
        const double top = std::cos(kPi * y / (map.height * kSub)),
                     bottom = std::cos(kPi * (y + 1.0) / (map.height * kSub));
        const double t = std::acos(std::clamp(0.5 * (top + bottom), -1.0, 1.0)) / kPi;
        const double cell = 2.0 * kPi / (map.width * kSub) * (top - bottom);
        for (int x = 0; x < map.width * kSub; ++x) {
            const glm::dvec3 d = environmentDirection((x + 0.5) / (map.width * kSub), t);
            const double cosine = glm::dot(normal, d);
            if (cosine > 0.0) sum += environmentRadiance(map, d) * (cosine * cell);
        }
    }
    return sum;
}

}  // namespace rad
