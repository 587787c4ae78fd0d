#include "lightmap/texel_footprints.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace rad {
namespace {

using Polygon = std::vector<glm::dvec2>;

// The part of `poly` where axis `axis` of a point is >= bound (keepAbove) or <= bound.
Polygon clipAgainst(const Polygon& poly, int axis, double bound, bool keepAbove) {
    Polygon out;
    const std::size_t n = poly.size();
    for (std::size_t i = 0; i < n; ++i) {
        const glm::dvec2 &a = poly[i], &b = poly[(i + 1) % n];
        const double da = keepAbove ? a[axis] - bound : bound - a[axis];
        const double db = keepAbove ? b[axis] - bound : bound - b[axis];
        if (da >= 0.0) out.push_back(a);
        if ((da >= 0.0) != (db >= 0.0)) {
            const double s = da / (da - db);
            glm::dvec2 p = a + s * (b - a);
            p[axis] = bound;  // exactly on the texel's edge
            out.push_back(p);
        }
    }
    return out;
}

double polygonArea(const Polygon& poly) {
    double twice = 0.0;
    for (std::size_t i = 0; i < poly.size(); ++i) {
        const glm::dvec2 &a = poly[i], &b = poly[(i + 1) % poly.size()];
        twice += a.x * b.y - b.x * a.y;
    }
    return 0.5 * std::fabs(twice);
}

// The point of a convex polygon nearest q, and its squared distance (0 inside).
std::pair<glm::dvec2, double> nearestPoint(const Polygon& poly, const glm::dvec2& q) {
    bool inside = true;
    double area = 0.0;
    for (std::size_t i = 0; i < poly.size(); ++i) {
        const glm::dvec2 &a = poly[i], &b = poly[(i + 1) % poly.size()];
        area += a.x * b.y - b.x * a.y;
    }
    glm::dvec2 best = poly[0];
    double bestDistance = HUGE_VAL;
    for (std::size_t i = 0; i < poly.size(); ++i) {
        const glm::dvec2 &a = poly[i], &b = poly[(i + 1) % poly.size()];
        const double side = (b.x - a.x) * (q.y - a.y) - (b.y - a.y) * (q.x - a.x);
        if (side * area < 0.0) inside = false;
        const glm::dvec2 e = b - a;
        const double t = glm::dot(e, e) > 0.0 ? std::clamp(glm::dot(q - a, e) / glm::dot(e, e), 0.0, 1.0) : 0.0;
        const glm::dvec2 p = a + t * e;
        const double d = glm::dot(q - p, q - p);
        if (d < bestDistance) {
            bestDistance = d;
            best = p;
        }
    }
    if (inside) return {q, 0.0};
    return {best, bestDistance};
}

struct Part {
    std::uint32_t texel;  // y * pageSize + x
    std::uint32_t face;
    glm::dvec2 anchor{0.0};       // the part's point nearest the texel's centre, in the face's barycentrics
    double anchorDistance = 0.0;  // squared, in texels
    std::vector<std::array<glm::dvec2, 3>> triangles;  // in the face's barycentrics (b1, b2)
    std::vector<double> areas;                         // m^2 each
};

}  // namespace

TexelFootprints texelFootprints(const LightmapLayout& layout, const Mesh& mesh, std::uint32_t page) {
    const std::uint32_t side = layout.pageSize;
    std::vector<Part> parts;
    for (std::uint32_t f = 0; f < mesh.faces.size(); ++f) {
        if (layout.pageOf[f] != page) continue;
        const std::array<glm::dvec2, 3>& t = layout.texels[f];
        const glm::dvec2 e1 = t[1] - t[0], e2 = t[2] - t[0];
        const double det = e1.x * e2.y - e2.x * e1.y;
        const Face& face = mesh.faces[f];
        const double area = 0.5 * glm::length(glm::cross(glm::dvec3(face.p[1]) - glm::dvec3(face.p[0]),
                                                         glm::dvec3(face.p[2]) - glm::dvec3(face.p[0])));
        if (!(std::fabs(det) > 0.0) || !(area > 0.0)) continue;  // no area to light
        const double metresPerTexelArea = area / (0.5 * std::fabs(det));
        const double lox = std::min({t[0].x, t[1].x, t[2].x}), hix = std::max({t[0].x, t[1].x, t[2].x});
        const double loy = std::min({t[0].y, t[1].y, t[2].y}), hiy = std::max({t[0].y, t[1].y, t[2].y});
        const auto x0 = static_cast<std::uint32_t>(std::clamp(std::floor(lox), 0.0, side - 1.0));
        const auto x1 = static_cast<std::uint32_t>(std::clamp(std::ceil(hix) - 1.0, 0.0, side - 1.0));
        const auto y0 = static_cast<std::uint32_t>(std::clamp(std::floor(loy), 0.0, side - 1.0));
        const auto y1 = static_cast<std::uint32_t>(std::clamp(std::ceil(hiy) - 1.0, 0.0, side - 1.0));
        for (std::uint32_t y = y0; y <= y1; ++y)
            for (std::uint32_t x = x0; x <= x1; ++x) {
                Polygon poly{t[0], t[1], t[2]};
                poly = clipAgainst(poly, 0, x, true);
                poly = clipAgainst(poly, 0, x + 1.0, false);
                poly = clipAgainst(poly, 1, y, true);
                poly = clipAgainst(poly, 1, y + 1.0, false);
                if (poly.size() < 3 || !(polygonArea(poly) > 1e-9)) continue;
                Part part;
                part.texel = y * side + x;
                part.face = f;
                // A fan of triangles, each corner in the face's barycentrics.
                auto bary = [&](const glm::dvec2& q) {
                    const glm::dvec2 d = q - t[0];
                    double b1 = std::clamp((d.x * e2.y - e2.x * d.y) / det, 0.0, 1.0);
                    double b2 = std::clamp((e1.x * d.y - d.x * e1.y) / det, 0.0, 1.0);
                    if (b1 + b2 > 1.0) {  // within the triangle, whatever the rounding
                        const double sum = b1 + b2;
                        b1 /= sum;
                        b2 /= sum;
                    }
                    return glm::dvec2(b1, b2);
                };
                // The anchor: the footprint's point nearest the centre, moved a thousandth of a
                // texel into the footprint where it lies on its edge, so that rounding never puts
                // it behind a wall that meets the face along that edge.
                auto [nearest, distance] = nearestPoint(poly, glm::dvec2(x + 0.5, y + 0.5));
                if (distance > 0.0) {
                    glm::dvec2 centroid(0.0);
                    for (const glm::dvec2& p : poly) centroid += p / static_cast<double>(poly.size());
                    const double apart = glm::length(centroid - nearest);
                    if (apart > 0.0) nearest += (centroid - nearest) * std::min(1.0, 1e-3 / apart);
                }
                part.anchor = bary(nearest);
                part.anchorDistance = distance;
                for (std::size_t k = 1; k + 1 < poly.size(); ++k) {
                    const double a = polygonArea({poly[0], poly[k], poly[k + 1]}) * metresPerTexelArea;
                    if (!(a > 0.0)) continue;
                    part.triangles.push_back({bary(poly[0]), bary(poly[k]), bary(poly[k + 1])});
                    part.areas.push_back(a);
                }
                if (!part.triangles.empty()) parts.push_back(std::move(part));
            }
    }
    // By texel, the faces in order within one (a stable sort keeps the faces' order).
    std::stable_sort(parts.begin(), parts.end(), [](const Part& a, const Part& b) { return a.texel < b.texel; });
    TexelFootprints out;
    for (std::size_t i = 0; i < parts.size();) {
        std::size_t j = i;
        double total = 0.0;
        while (j < parts.size() && parts[j].texel == parts[i].texel) {
            for (double a : parts[j].areas) total += a;
            ++j;
        }
        double running = 0.0;
        for (std::size_t k = i + 1; k < j; ++k)
            if (layout.chartOf[parts[k].face] != layout.chartOf[parts[i].face]) {
                ++out.sharedTexels;
                break;
            }
        std::size_t anchor = i;  // the first part nearest the centre
        for (std::size_t k = i + 1; k < j; ++k)
            if (parts[k].anchorDistance < parts[anchor].anchorDistance) anchor = k;
        out.anchors.push_back({static_cast<float>(parts[anchor].anchor.x), static_cast<float>(parts[anchor].anchor.y),
                               parts[anchor].face, 0u});
        for (std::size_t k = i; k < j; ++k)
            for (std::size_t p = 0; p < parts[k].triangles.size(); ++p) {
                running += parts[k].areas[p];
                TexelPiece piece{};
                for (int c = 0; c < 3; ++c) {
                    piece.b[c][0] = static_cast<float>(parts[k].triangles[p][static_cast<std::size_t>(c)].x);
                    piece.b[c][1] = static_cast<float>(parts[k].triangles[p][static_cast<std::size_t>(c)].y);
                }
                piece.end = static_cast<float>(running / total);
                piece.face = parts[k].face;
                out.pieces.push_back(piece);
            }
        out.pieces.back().end = 1.0f;
        out.texels.push_back(parts[i].texel);
        out.ends.push_back(static_cast<rad_uint>(out.pieces.size()));
        out.area.push_back(total);
        i = j;
    }
    return out;
}

}  // namespace rad
