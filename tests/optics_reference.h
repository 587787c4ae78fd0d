#pragma once
// Closed forms of optics the tests check kernels/material.h against, in double.

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "scene/ggx_albedo.h"

namespace rad::test {

// The dielectric Fresnel reflectance (unpolarised) for light meeting the surface at cosine
// `cosi` from the side where the ratio of indices (this side's over the other's) is eta; 1 beyond
// the critical angle.
inline double dielectricFresnel(double cosi, double eta) {
    const double sin2t = eta * eta * (1.0 - cosi * cosi);
    if (sin2t >= 1.0) return 1.0;
    const double ct = std::sqrt(1.0 - sin2t);
    const double rs = (eta * cosi - ct) / (eta * cosi + ct), rp = (eta * ct - cosi) / (eta * ct + cosi);
    return 0.5 * (rs * rs + rp * rp);
}

// glTF's rough metal (kernels/ggx.h) written out independently: GGX of roughness alpha about the
// unit normal n, Smith's height-correlated masking-shadowing, Schlick's Fresnel from f0.
inline double ggxLambda(const glm::dvec3& n, const glm::dvec3& w, double alpha) {
    const double c = glm::dot(n, w);
    return 0.5 * (std::sqrt(1.0 + alpha * alpha * (1.0 - c * c) / (c * c)) - 1.0);
}

inline double ggxDistribution(const glm::dvec3& n, const glm::dvec3& m, double alpha) {
    const double c = glm::dot(n, m), a2 = alpha * alpha, d = c * c * (a2 - 1.0) + 1.0;
    return a2 / (M_PI * d * d);
}

inline double schlickFresnel(double f0, double cosine) {
    return f0 + (1.0 - f0) * std::pow(1.0 - cosine, 5.0);
}

// f(wo, wi) cos(wi, n) for unit directions away from the surface; 0 where either is below it.
inline double ggxReflection(const glm::dvec3& n, const glm::dvec3& wo, const glm::dvec3& wi, double alpha, double f0) {
    const double co = glm::dot(n, wo), ci = glm::dot(n, wi);
    if (co <= 0.0 || ci <= 0.0) return 0.0;
    const glm::dvec3 h = glm::normalize(wo + wi);
    const double g2 = 1.0 / (1.0 + ggxLambda(n, wo, alpha) + ggxLambda(n, wi, alpha));
    return ggxDistribution(n, h, alpha) * g2 * schlickFresnel(f0, glm::dot(wo, h)) / (4.0 * co);
}

// Rough glass's reflection: ggxReflection with the dielectric Fresnel reflectance at the
// microfacet, from the side where the ratio of indices is eta (no energy scale).
inline double ggxDielectricReflection(const glm::dvec3& n, const glm::dvec3& wo, const glm::dvec3& wi, double alpha,
                                      double eta) {
    const double co = glm::dot(n, wo), ci = glm::dot(n, wi);
    if (co <= 0.0 || ci <= 0.0) return 0.0;
    const glm::dvec3 h = glm::normalize(wo + wi);
    const double g2 = 1.0 / (1.0 + ggxLambda(n, wo, alpha) + ggxLambda(n, wi, alpha));
    return ggxDistribution(n, h, alpha) * g2 * dielectricFresnel(glm::dot(wo, h), eta) / (4.0 * co);
}

// The share of the light arriving at cosine `cosine` to a rough metal's normal that it
// reflects (its directional albedo), by the midpoint rule on n x n points of Walter et al.'s map
// of the square to microfacet normals distributed as D(h) cos(theta_h) (not the kernels' sampling
// of visible normals): dw_i = 4 (wo . h) dw_h, so the integrand over that density is
// F G2 (wo . h) / (wo.z h.z). `moment` weighs each reflected direction (local, z the normal).
template <class Moment>
double ggxAlbedo(double cosine, double alpha, double f0, Moment moment, int n = 1500) {
    const glm::dvec3 up(0.0, 0.0, 1.0), wo(std::sqrt(1.0 - cosine * cosine), 0.0, cosine);
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
        const double xi = (i + 0.5) / n, theta = std::atan(alpha * std::sqrt(xi / (1.0 - xi)));
        for (int k = 0; k < n; ++k) {
            const double phi = 2.0 * M_PI * (k + 0.5) / n;
            const glm::dvec3 h(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
            const double oh = glm::dot(wo, h);
            if (oh <= 0.0) continue;
            const glm::dvec3 wi = 2.0 * oh * h - wo;
            if (wi.z <= 0.0) continue;
            const double g2 = 1.0 / (1.0 + ggxLambda(up, wo, alpha) + ggxLambda(up, wi, alpha));
            sum += moment(wi) * schlickFresnel(f0, oh) * g2 * oh / (wo.z * h.z);
        }
    }
    return sum / (static_cast<double>(n) * n);
}

inline double ggxAlbedo(double cosine, double alpha, double f0, int n = 1500) {
    return ggxAlbedo(
        cosine, alpha, f0, [](const glm::dvec3&) { return 1.0; }, n);
}

// What the kernels scale a GGX lobe of roughness sqrt(alpha), F0 f0 and F90 f90 by toward a
// viewer at cosine `cosine` (kernels/material.h: ggx_energy): the program's definition, E1 and
// its mean read from the program's table (scene/ggx_albedo.h) as the kernels read them, so that
// a test's quadrature checks the single-scattering lobe and the scale is the program's own.
inline double ggxEnergy(double cosine, double alpha, double f0, double f90 = 1.0) {
    const double r = std::sqrt(alpha);
    return ggxEnergyScale(ggxAlbedoTable().at(cosine, r)[0], ggxAlbedoTable().averageAt(r)[0], f0, f90);
}

// ggxAlbedo with the energy scale: what a rough metal reflects (a white one all it receives).
inline double ggxEnergyAlbedo(double cosine, double alpha, double f0, int n = 1500) {
    return ggxAlbedo(cosine, alpha, f0, n) * ggxEnergy(cosine, alpha, f0);
}

// The radiance seen straight from above at (x, 0, z) on a rough metal floor (normal +y; GGX
// alpha, F0 f0) lit by a point light of 1 W/sr at (0, height, 0), per unit of its intensity: f
// cos_i / r^2. Its mean over the square |x|, |z| <= half, by the midpoint rule on n x n points.
// The same for a light at `light` (y > 0), anywhere.
inline double highlightOnRoughFloor(double x, double z, const glm::dvec3& light, double alpha, double f0) {
    const glm::dvec3 toLight = light - glm::dvec3(x, 0.0, z);
    const double r2 = glm::dot(toLight, toLight);
    return ggxReflection({0, 1, 0}, {0, 1, 0}, toLight / std::sqrt(r2), alpha, f0) / r2;
}

inline double highlightOnRoughFloor(double x, double z, double height, double alpha, double f0) {
    return highlightOnRoughFloor(x, z, glm::dvec3(0.0, height, 0.0), alpha, f0);
}

inline double meanHighlightOnRoughFloor(double half, const glm::dvec3& light, double alpha, double f0, int n = 400) {
    double sum = 0.0;
    for (int i = 0; i < n; ++i)
        for (int k = 0; k < n; ++k)
            sum += highlightOnRoughFloor(half * (2.0 * (i + 0.5) / n - 1.0), half * (2.0 * (k + 0.5) / n - 1.0), light,
                                         alpha, f0);
    return sum / (static_cast<double>(n) * n);
}

inline double meanHighlightOnRoughFloor(double half, double height, double alpha, double f0, int n = 400) {
    return meanHighlightOnRoughFloor(half, glm::dvec3(0.0, height, 0.0), alpha, f0, n);
}

// The same for a floor of rough glass seen from above (ratio of indices eta): f cos_i / r^2 of
// its reflection, the mean over |x|, |z| <= half under a light of 1 W/sr at (0, height, 0); with
// `through`, of what a thin pane passes of a light at (0, -height, 0) below it (untinted): its
// reflection mirrored through the pane (the same geometry as the light above) times 1 - Fresnel.
inline double meanHighlightOnRoughPane(double half, double height, double alpha, double eta, bool through = false,
                                       int n = 400) {
    double sum = 0.0;
    for (int i = 0; i < n; ++i)
        for (int k = 0; k < n; ++k) {
            const double x = half * (2.0 * (i + 0.5) / n - 1.0), z = half * (2.0 * (k + 0.5) / n - 1.0);
            const glm::dvec3 toLight = glm::dvec3(0.0, height, 0.0) - glm::dvec3(x, 0.0, z);
            const double r2 = glm::dot(toLight, toLight);
            const glm::dvec3 wi = toLight / std::sqrt(r2);
            const double reflected = ggxDielectricReflection({0, 1, 0}, {0, 1, 0}, wi, alpha, eta);
            if (!through) {
                sum += reflected / r2;
                continue;
            }
            const double fresnel = dielectricFresnel(glm::dot(glm::dvec3(0, 1, 0), glm::normalize(glm::dvec3(0, 1, 0) + wi)), eta);
            sum += reflected / fresnel * (1.0 - fresnel) / r2;
        }
    return sum / (static_cast<double>(n) * n);
}

}  // namespace rad::test
