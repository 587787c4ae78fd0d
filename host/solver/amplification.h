#pragma once
// How much a scene amplifies its light, measured as a progressive solve runs, and what the
// solver does about it when it is large (reflectance near 1: integrating spheres, white rooms,
// snow).
//
// In power form every shot of power P sends back r P as new unshot power, r the scene's return
// ratio (its reflectance as the light sees it: what is neither absorbed nor escapes), so all
// the power that ever flows is G = 1 / (1 - r) times the power there was to shoot. Measured
// here from the solve's own totals: of the power shot so far (S, per channel) the unshot power
// now (U) says how much came back, generated = S + U - E (E: the power there was to shoot at
// the start), r = generated / S.
//
// The measure is taken per channel, and only once a channel has shot twice the power it had to
// shoot (two generations' worth: the first bounce alone can return far more than the scene
// does, a lamp aimed at a white ceiling over a dark floor). Two consequences where a channel's
// G exceeds kThreshold (a return ratio of 0.75), so scenes that amplify their light less are
// solved exactly as before:
//   - Shots. The unshot power shrinks by r per generation of shots: 916 generations to 1e-4 at
//     r = 0.99. Overshooting (Feda and Purgathofer 1992) lets each shooter also shoot now the
//     power it is expected still to receive: rho_j A_j K, with K the irradiance the unshot
//     power U will bring in all its future bounces spread as ambient light over the scene
//     (K = U r / (1 - r) / sum_j rho_j A_j, per channel). A patch that shot more than it then
//     receives owes the difference (negative unshot power) and shoots it back, negative, later;
//     what is left converges to zero as before, in a few generations instead of hundreds. Every
//     watt shot is delivered by rays, whatever K is. Only where every patch is one element: a
//     patch's rays start from its elements in proportion to what each received, and power
//     shot ahead of its arrival would leave from the wrong ones.
//   - Rays. Every ray carries the same power p. A radiosity made of n rays has a relative noise
//     of about 1 / sqrt(n), and at gain G the light flows G times, so p can grow to (emitted /
//     N) x G / kThreshold and leave each radiosity's noise where a gain of kThreshold has it.
//     But the level of all the light is noisy too where rays' fates differ (some escape, some
//     land on darker surfaces): its relative variance is p G v / emitted, v the variance of the
//     reflectance a ray's power meets, at most r (rho_max - r). So p grows only as far as that
//     also stays within a gain-kThreshold scene's, and by the channel that allows the least
//     (rayPowerScale): in a closed room of one reflectance (v = 0) fully, in open or mixed
//     scenes little or not at all.
// Everything here is a pure function of the solve's state, so every process of a run, and a
// resumed solve, make the same choices.

#include <vector>

#include <glm/vec3.hpp>

#include "shared_types.h"

namespace rad {

class Amplification {
public:
    static constexpr double kThreshold = 4.0;

    // toShoot: the power there was to shoot at the start, per channel; reflectedArea: sum of
    // rho_j A_j over the patches; maxReflectance: the largest rho_j, per channel; shot: the power
    // shot so far (a resumed solve's tally); threshold: the gain above which the solve acts
    // (infinity: never); overshootAllowed: false where patches hold several elements.
    Amplification(const glm::dvec3& toShoot, const glm::dvec3& reflectedArea, const glm::dvec3& maxReflectance,
                  const glm::dvec3& shot, double threshold = kThreshold, bool overshootAllowed = true);

    void addShot(const Shooter& shooter);
    // The unshot power now, from the gather kernel's partials (their signed sums per channel).
    void update(const std::vector<UnshotPartial>& partials);

    const glm::dvec3& shot() const { return shot_; }
    bool measured(int channel) const;       // shot twice what it had to shoot
    double returnRatio(int channel) const;  // r; 0 until measured
    double gain(int channel) const;         // G = 1 / (1 - r)
    bool large() const;                     // some channel's G above the threshold
    // The power of a ray over emitted / N: 1 unless every channel shot allows more (above).
    double rayPowerScale() const;
    // K per channel (device units of power per m^2) for the channels whose G is large; else 0.
    glm::vec3 overshoot() const;

private:
    glm::dvec3 toShoot_, reflectedArea_, maxReflectance_, shot_, unshot_;
    double threshold_;
    bool overshootAllowed_;
};

}  // namespace rad
