#include "scene/ggx_albedo.h"

#include <algorithm>
#include <cmath>

namespace rad {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kStrata = 64;

struct V3 {
    double x, y, z;
};

double lambda(const V3& w, double alpha) {
    const double tan2 = (w.x * w.x + w.y * w.y) / (w.z * w.z);
    return 0.5 * (std::sqrt(1.0 + alpha * alpha * tan2) - 1.0);
}

V3 normalized(const V3& v) {
    const double l = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    return {v.x / l, v.y / l, v.z / l};
}

// A microfacet normal visible from wo, drawn from a point of the unit disk (radius, and the
// cosine and sine of its angle) (Heitz 2018).
V3 visibleNormal(const V3& wo, double alpha, double radius, double cosPhi, double sinPhi) {
    const V3 v = normalized({alpha * wo.x, alpha * wo.y, wo.z});
    const double len2 = v.x * v.x + v.y * v.y;
    const V3 t1 = len2 > 0.0 ? V3{-v.y / std::sqrt(len2), v.x / std::sqrt(len2), 0.0} : V3{1.0, 0.0, 0.0};
    const V3 t2{v.y * t1.z - v.z * t1.y, v.z * t1.x - v.x * t1.z, v.x * t1.y - v.y * t1.x};
    const double p1 = radius * cosPhi;
    const double s = 0.5 * (1.0 + v.z);
    const double p2 = (1.0 - s) * std::sqrt(std::max(0.0, 1.0 - p1 * p1)) + s * radius * sinPhi;
    const double h = std::sqrt(std::max(0.0, 1.0 - p1 * p1 - p2 * p2));
    const V3 n{p1 * t1.x + p2 * t2.x + h * v.x, p1 * t1.y + p2 * t2.y + h * v.y, p1 * t1.z + p2 * t2.z + h * v.z};
    return normalized({alpha * n.x, alpha * n.y, std::max(1e-12, n.z)});
}

}  // namespace

std::array<double, 2> ggxAlbedo(double mu, double roughness, int strata) {
    mu = std::clamp(mu, 1e-3, 1.0);
    const double alpha = roughness * roughness;
    const V3 wo{std::sqrt(1.0 - mu * mu), 0.0, mu};
    const double lo = lambda(wo, alpha);
    std::vector<double> cosines(static_cast<std::size_t>(strata)), sines(cosines.size());
    for (int b = 0; b < strata; ++b) {
        cosines[static_cast<std::size_t>(b)] = std::cos(2.0 * kPi * (b + 0.5) / strata);
        sines[static_cast<std::size_t>(b)] = std::sin(2.0 * kPi * (b + 0.5) / strata);
    }
    // The disk's radius squared is u = 1 - (1 - v)^2, v in midpoint strata, each weighted by
    // du / dv: strata crowd the disk's rim, where a smooth lobe's few steep microfacets (those
    // that send light below the horizon) lie.
    double e1 = 0.0, e5 = 0.0;
    for (int a = 0; a < strata; ++a) {
        const double v = (a + 0.5) / strata, jacobian = 2.0 * (1.0 - v);
        const double radius = std::sqrt(1.0 - (1.0 - v) * (1.0 - v));
        for (int b = 0; b < strata; ++b) {
            const V3 m = visibleNormal(wo, alpha, radius, cosines[static_cast<std::size_t>(b)],
                                       sines[static_cast<std::size_t>(b)]);
            const double om = wo.x * m.x + wo.y * m.y + wo.z * m.z;
            const V3 wi{2.0 * om * m.x - wo.x, 2.0 * om * m.y - wo.y, 2.0 * om * m.z - wo.z};
            if (!(wi.z > 0.0)) continue;  // shadowed: lost to single scattering
            const double weight = (1.0 + lo) / (1.0 + lo + lambda(wi, alpha));
            const double q = 1.0 - std::clamp(om, 0.0, 1.0), q2 = q * q;
            e1 += jacobian * weight;
            e5 += jacobian * weight * q2 * q2 * q;
        }
    }
    const double n = static_cast<double>(strata) * strata;
    return {e1 / n, e5 / n};
}

const GgxAlbedoTable& ggxAlbedoTable() {
    static const GgxAlbedoTable table = [] {
        GgxAlbedoTable t;
        t.values.resize(2 * kAlbedoCosines * kAlbedoRoughness);
        for (std::size_t j = 0; j < kAlbedoRoughness; ++j) {
            const double r = static_cast<double>(j) / (kAlbedoRoughness - 1);
            double sum1 = 0.0, sum5 = 0.0;
            for (std::size_t i = 0; i < kAlbedoCosines; ++i) {
                const double s = static_cast<double>(i) / (kAlbedoCosines - 1);
                const auto e = ggxAlbedo(s * s, r, kStrata);
                t.values[2 * (j * kAlbedoCosines + i)] = static_cast<float>(e[0]);
                t.values[2 * (j * kAlbedoCosines + i) + 1] = static_cast<float>(e[1]);
            }
            // 2 integral E mu dmu by the trapezoid rule on the table's own rows (E is smooth in
            // mu; the rule's error is below 1e-4 of the average)
            for (std::size_t i = 0; i + 1 < kAlbedoCosines; ++i) {
                const double s0 = static_cast<double>(i) / (kAlbedoCosines - 1), m0 = s0 * s0;
                const double s1 = static_cast<double>(i + 1) / (kAlbedoCosines - 1), m1 = s1 * s1;
                const std::size_t a = 2 * (j * kAlbedoCosines + i), b = a + 2;
                sum1 += (t.values[a] * m0 + t.values[b] * m1) * (m1 - m0);
                sum5 += (t.values[a + 1] * m0 + t.values[b + 1] * m1) * (m1 - m0);
            }
            t.average1[j] = sum1;
            t.average5[j] = sum5;
        }
        return t;
    }();
    return table;
}

std::array<double, 2> GgxAlbedoTable::at(double mu, double roughness) const {
    const double x = std::sqrt(std::clamp(mu, 0.0, 1.0)) * (kAlbedoCosines - 1);
    const double y = std::clamp(roughness, 0.0, 1.0) * (kAlbedoRoughness - 1);
    const std::size_t i = std::min<std::size_t>(static_cast<std::size_t>(x), kAlbedoCosines - 2);
    const std::size_t j = std::min<std::size_t>(static_cast<std::size_t>(y), kAlbedoRoughness - 2);
    const double fx = x - i, fy = y - j;
    std::array<double, 2> out{};
    for (int k = 0; k < 2; ++k) {
        const auto v = [&](std::size_t ii, std::size_t jj) { return values[2 * (jj * kAlbedoCosines + ii) + k]; };
        out[k] = (1 - fy) * ((1 - fx) * v(i, j) + fx * v(i + 1, j)) + fy * ((1 - fx) * v(i, j + 1) + fx * v(i + 1, j + 1));
    }
    return out;
}

std::array<double, 2> GgxAlbedoTable::averageAt(double roughness) const {
    const double y = std::clamp(roughness, 0.0, 1.0) * (kAlbedoRoughness - 1);
    const std::size_t j = std::min<std::size_t>(static_cast<std::size_t>(y), kAlbedoRoughness - 2);
    const double f = y - j;
    return {(1 - f) * average1[j] + f * average1[j + 1], (1 - f) * average5[j] + f * average5[j + 1]};
}

std::vector<float> ggxAlbedoDeviceTable() {
    const GgxAlbedoTable& table = ggxAlbedoTable();
    std::vector<float> out = table.values;
    for (std::size_t j = 0; j < kAlbedoRoughness; ++j) {
        out.push_back(static_cast<float>(table.average1[j]));
        out.push_back(static_cast<float>(table.average5[j]));
    }
    return out;
}

double ggxEnergyScale(double e1, double e1Average, double f0, double f90) {
    const double favg = f0 + (f90 - f0) / 21.0;
    const double fms = favg * e1Average / (1.0 - favg * (1.0 - e1Average));
    return 1.0 + fms * (1.0 - e1) / std::max(e1, 1e-3);
}

}  // namespace rad
