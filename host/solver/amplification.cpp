#include "solver/amplification.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rad {
namespace {

// Return ratios are kept below this: K and G stay finite however near 1 the measure comes, and
// a batch's signed fixed-point sums keep their headroom (G <= 1000).
constexpr double kMostReturned = 0.999;

}  // namespace

Amplification::Amplification(const glm::dvec3& toShoot, const glm::dvec3& reflectedArea,
                             const glm::dvec3& maxReflectance, const glm::dvec3& shot, double threshold,
                             bool overshootAllowed)
    : toShoot_(toShoot),
      reflectedArea_(reflectedArea),
      maxReflectance_(maxReflectance),
      shot_(shot),
      unshot_(toShoot),
      threshold_(threshold),
      overshootAllowed_(overshootAllowed) {}

void Amplification::addShot(const Shooter& shooter) {
    for (int c = 0; c < 3; ++c) shot_[c] += static_cast<double>(shooter.taken[c]);
}

void Amplification::update(const std::vector<UnshotPartial>& partials) {
    unshot_ = glm::dvec3(0.0);
    for (const UnshotPartial& p : partials)
        for (int c = 0; c < 3; ++c) unshot_[c] += static_cast<double>(p.sums[c]);
}

bool Amplification::measured(int c) const {
    return toShoot_[c] > 0.0 && shot_[c] >= 2.0 * toShoot_[c];
}

double Amplification::returnRatio(int c) const {
    if (!measured(c)) return 0.0;
    return std::clamp((shot_[c] + unshot_[c] - toShoot_[c]) / shot_[c], 0.0, kMostReturned);
}

double Amplification::gain(int c) const {
    return 1.0 / (1.0 - returnRatio(c));
}

bool Amplification::large() const {
    for (int c = 0; c < 3; ++c)
        if (gain(c) > threshold_) return true;
    return false;
}

double Amplification::rayPowerScale() const {
    // A gain-`threshold` scene's level noise, threshold x r (1 - r) at r = 1 - 1 / threshold.
    const double reference = (threshold_ - 1.0) / threshold_;
    const double most = std::max({shot_.x, shot_.y, shot_.z});
    double scale = std::numeric_limits<double>::infinity();
    for (int c = 0; c < 3; ++c) {
        if (!(shot_[c] > 1e-3 * most)) continue;  // a channel hardly shot says nothing
        const double r = returnRatio(c), g = gain(c);
        const double spread = std::max(0.0, r * (maxReflectance_[c] - r));  // >= the per-ray variance
        const double own = std::min(g / threshold_, spread > 0.0 ? reference / (spread * g) : g / threshold_);
        scale = std::min(scale, std::max(1.0, own));
    }
    return std::isfinite(scale) ? scale : 1.0;
}

glm::vec3 Amplification::overshoot() const {
    glm::vec3 k(0.0f);
    if (!overshootAllowed_) return k;
    for (int c = 0; c < 3; ++c) {
        if (!(gain(c) > threshold_) || !(reflectedArea_[c] > 0.0)) continue;
        const double r = returnRatio(c);
        k[c] = static_cast<float>(unshot_[c] * r / (1.0 - r) / reflectedArea_[c]);
    }
    return k;
}

}  // namespace rad
