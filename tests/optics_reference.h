#pragma once
// Closed forms of optics the tests check kernels/specular.h against, in double.

#include <cmath>

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

}  // namespace rad::test
