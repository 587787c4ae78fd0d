#include "util/analytic_form_factors.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/geometric.hpp>

#include "shared_math.h"

namespace rad {
namespace {

// Nodes and weights of n-point Gauss-Legendre quadrature on [0, 1], by Newton's method on the
// Legendre polynomial from the Chebyshev guesses.
struct Quadrature {
    std::vector<double> x, w;
};

Quadrature gaussLegendre(int n) {
    Quadrature q;
    q.x.resize(static_cast<std::size_t>(n));
    q.w.resize(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
        double z = std::cos(kPi * (i + 0.75) / (n + 0.5));
        double derivative = 1.0;
        for (int iteration = 0; iteration < 100; ++iteration) {
            double p0 = 1.0, p1 = 0.0;
            for (int k = 1; k <= n; ++k) {
                const double p2 = p1;
                p1 = p0;
                p0 = ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p2) / k;
            }
            derivative = n * (z * p0 - p1) / (z * z - 1.0);
            const double step = p0 / derivative;
            z -= step;
            if (std::fabs(step) < 1e-15) break;
        }
        q.x[static_cast<std::size_t>(i)] = 0.5 * (1.0 - z);
        q.w[static_cast<std::size_t>(i)] = 1.0 / ((1.0 - z * z) * derivative * derivative);  // 2/(..) on [-1,1], halved
    }
    return q;
}

double pointSegmentDistance(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b) {
    const glm::dvec3 ab = b - a;
    const double t = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0, 1.0);
    return glm::length(p - (a + t * ab));
}

// ln r is smooth on two edges far apart compared with their length: one Gauss-Legendre rule
// per edge suffices there; close edges are cut into more pieces.
int piecesFor(const glm::dvec3& a0, const glm::dvec3& a1, const glm::dvec3& b0, const glm::dvec3& b1) {
    const double distance = std::min({pointSegmentDistance(a0, b0, b1), pointSegmentDistance(a1, b0, b1),
                                      pointSegmentDistance(b0, a0, a1), pointSegmentDistance(b1, a0, a1)});
    const double length = std::max(glm::length(a1 - a0), glm::length(b1 - b0));
    if (distance <= 0.0) return 16;
    return static_cast<int>(std::clamp(std::ceil(2.0 * length / distance), 1.0, 16.0));
}

}  // namespace

double pointToPolygonFactor(const glm::dvec3& point, const glm::dvec3& normal, const std::vector<glm::dvec3>& polygon) {
    double sum = 0.0;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const glm::dvec3 a = glm::normalize(polygon[i] - point);
        const glm::dvec3 b = glm::normalize(polygon[(i + 1) % polygon.size()] - point);
        const glm::dvec3 c = glm::cross(a, b);
        const double s = glm::length(c);
        if (s == 0.0) continue;
        const double angle = std::atan2(s, glm::dot(a, b));
        sum += angle * glm::dot(normal, c / s);
    }
    return std::fabs(sum) / (2.0 * kPi);
}

double polygonArea(const std::vector<glm::dvec3>& polygon) {
    glm::dvec3 sum(0.0);
    for (std::size_t i = 0; i < polygon.size(); ++i) sum += glm::cross(polygon[i], polygon[(i + 1) % polygon.size()]);
    return 0.5 * glm::length(sum);
}

double polygonToPolygonFactor(const std::vector<glm::dvec3>& from, const std::vector<glm::dvec3>& to) {
    static const Quadrature q = gaussLegendre(20);
    double sum = 0.0;
    for (std::size_t i = 0; i < from.size(); ++i) {
        const glm::dvec3 a0 = from[i], a1 = from[(i + 1) % from.size()];
        for (std::size_t j = 0; j < to.size(); ++j) {
            const glm::dvec3 b0 = to[j], b1 = to[(j + 1) % to.size()];
            const double dot = glm::dot(a1 - a0, b1 - b0);
            if (dot == 0.0) continue;
            const int pieces = piecesFor(a0, a1, b0, b1);
            double integral = 0.0;
            for (int pa = 0; pa < pieces; ++pa)
                for (std::size_t ka = 0; ka < q.x.size(); ++ka) {
                    const glm::dvec3 x = a0 + ((pa + q.x[ka]) / pieces) * (a1 - a0);
                    for (int pb = 0; pb < pieces; ++pb)
                        for (std::size_t kb = 0; kb < q.x.size(); ++kb) {
                            const glm::dvec3 y = b0 + ((pb + q.x[kb]) / pieces) * (b1 - b0);
                            integral += q.w[ka] * q.w[kb] * std::log(glm::length(y - x));
                        }
                }
            sum += integral * dot / (pieces * pieces);
        }
    }
    return std::fabs(sum) / (2.0 * kPi * polygonArea(from));
}

double parallelSquaresFactor(double side, double gap) {
    const double x = side / gap, y = side / gap;
    const double x1 = 1.0 + x * x, y1 = 1.0 + y * y;
    const double f = std::log(std::sqrt(x1 * y1 / (1.0 + x * x + y * y))) +
                     x * std::sqrt(y1) * std::atan(x / std::sqrt(y1)) + y * std::sqrt(x1) * std::atan(y / std::sqrt(x1)) -
                     x * std::atan(x) - y * std::atan(y);
    return 2.0 * f / (kPi * x * y);
}

double perpendicularSquaresFactor() {
    // Rectangles w x h sharing an edge of length l, here all 1: H = W = 1.
    const double h = 1.0, w = 1.0;
    const double a = (1.0 + w * w) * (1.0 + h * h) / (1.0 + w * w + h * h);
    const double b = w * w * (1.0 + w * w + h * h) / ((1.0 + w * w) * (w * w + h * h));
    const double c = h * h * (1.0 + h * h + w * w) / ((1.0 + h * h) * (h * h + w * w));
    const double f = w * std::atan(1.0 / w) + h * std::atan(1.0 / h) - std::sqrt(h * h + w * w) * std::atan(1.0 / std::sqrt(h * h + w * w)) +
                     0.25 * std::log(a * std::pow(b, w * w) * std::pow(c, h * h));
    return f / (kPi * w);
}

double coaxialDisksFactor(double r1, double r2, double gap) {
    const double R1 = r1 / gap, R2 = r2 / gap;
    const double x = 1.0 + (1.0 + R2 * R2) / (R1 * R1);
    return 0.5 * (x - std::sqrt(x * x - 4.0 * (R2 / R1) * (R2 / R1)));
}

}  // namespace rad
