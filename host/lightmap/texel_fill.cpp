#include "lightmap/texel_fill.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <glm/geometric.hpp>

#include "shared_math.h"
#include "util/error.h"

namespace rad {
namespace {

// Taps of a bilinear lookup: texel indices in the page and their weights.
struct Taps {
    std::array<std::uint32_t, 4> texel{};
    std::array<double, 4> weight{};
};

Taps bilinearTaps(std::uint32_t size, glm::dvec2 at) {
    const glm::dvec2 c = at - 0.5;
    const double fx = std::floor(c.x), fy = std::floor(c.y);
    const double tx = c.x - fx, ty = c.y - fy;
    auto index = [&](double x, double y) {
        const auto ix = static_cast<std::uint32_t>(std::clamp(x, 0.0, size - 1.0));
        const auto iy = static_cast<std::uint32_t>(std::clamp(y, 0.0, size - 1.0));
        return iy * size + ix;
    };
    Taps t;
    t.texel = {index(fx, fy), index(fx + 1, fy), index(fx, fy + 1), index(fx + 1, fy + 1)};
    t.weight = {(1 - tx) * (1 - ty), tx * (1 - ty), (1 - tx) * ty, tx * ty};
    return t;
}

double luminance(const glm::vec3& c) {
    return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
}

}  // namespace

glm::vec3 bilinear(const std::vector<glm::vec3>& page, std::uint32_t size, glm::dvec2 at) {
    const Taps t = bilinearTaps(size, at);
    glm::dvec3 sum(0.0);
    for (int k = 0; k < 4; ++k)
        sum += t.weight[static_cast<std::size_t>(k)] * glm::dvec3(page[t.texel[static_cast<std::size_t>(k)]]);
    return glm::vec3(sum);
}

void fillGutters(BakedLightmap& lightmap, std::uint32_t rings) {
    const std::uint32_t size = lightmap.size;
    for (LightmapPage& page : lightmap.pages) {
        std::vector<bool> filled(page.area.size());
        for (std::size_t i = 0; i < filled.size(); ++i) filled[i] = page.area[i] > 0.0;
        // Rings: each reads only what the rings before it filled, so the order of the texels
        // does not matter.
        for (std::uint32_t ring = 0; ring < rings; ++ring) {
            std::vector<bool> next = filled;
            for (std::uint32_t y = 0; y < size; ++y)
                for (std::uint32_t x = 0; x < size; ++x) {
                    const std::size_t i = std::size_t{y} * size + x;
                    if (filled[i]) continue;
                    glm::dvec3 e(0.0), l(0.0);
                    int count = 0;
                    for (int dy = -1; dy <= 1; ++dy)
                        for (int dx = -1; dx <= 1; ++dx) {
                            const long nx = static_cast<long>(x) + dx, ny = static_cast<long>(y) + dy;
                            if (nx < 0 || ny < 0 || nx >= size || ny >= size) continue;
                            const std::size_t j = static_cast<std::size_t>(ny) * size + static_cast<std::size_t>(nx);
                            if (!filled[j]) continue;
                            e += glm::dvec3(page.irradiance[j]);
                            l += glm::dvec3(page.radiance[j]);
                            ++count;
                        }
                    if (count == 0) continue;
                    page.irradiance[i] = glm::vec3(e / static_cast<double>(count));
                    page.radiance[i] = glm::vec3(l / static_cast<double>(count));
                    next[i] = true;
                }
            filled = std::move(next);
        }
        // Pull-push for the rest: the mean of the filled texels in blocks of 2^k, the finest
        // block that has any giving an empty texel its value.
        std::vector<std::vector<glm::dvec3>> sumE{std::vector<glm::dvec3>(filled.size())}, sumL = sumE;
        std::vector<std::vector<double>> count{std::vector<double>(filled.size())};
        for (std::size_t i = 0; i < filled.size(); ++i)
            if (filled[i]) {
                sumE[0][i] = glm::dvec3(page.irradiance[i]);
                sumL[0][i] = glm::dvec3(page.radiance[i]);
                count[0][i] = 1.0;
            }
        std::vector<std::uint32_t> sides{size};
        while (sides.back() > 1) {
            const std::uint32_t from = sides.back(), to = (from + 1) / 2;
            std::vector<glm::dvec3> e(std::size_t{to} * to), l(e.size());
            std::vector<double> c(e.size());
            for (std::uint32_t y = 0; y < from; ++y)
                for (std::uint32_t x = 0; x < from; ++x) {
                    const std::size_t i = std::size_t{y} * from + x, j = std::size_t{y / 2} * to + x / 2;
                    e[j] += sumE.back()[i];
                    l[j] += sumL.back()[i];
                    c[j] += count.back()[i];
                }
            sumE.push_back(std::move(e));
            sumL.push_back(std::move(l));
            count.push_back(std::move(c));
            sides.push_back(to);
        }
        for (std::uint32_t y = 0; y < size; ++y)
            for (std::uint32_t x = 0; x < size; ++x) {
                const std::size_t i = std::size_t{y} * size + x;
                if (filled[i]) continue;
                for (std::size_t level = 1; level < sides.size(); ++level) {
                    const std::size_t j = std::size_t{y >> level} * sides[level] + (x >> level);
                    if (count[level][j] > 0.0) {
                        page.irradiance[i] = glm::vec3(sumE[level][j] / count[level][j]);
                        page.radiance[i] = glm::vec3(sumL[level][j] / count[level][j]);
                        break;
                    }
                }
            }
    }
}

std::vector<SeamPoint> seamPoints(const LightmapLayout& layout, const Mesh& mesh, double creaseDegrees) {
    // Faces' edges by their corners' positions (the lower corner first).
    using Corner = std::array<float, 3>;
    std::map<std::pair<Corner, Corner>, std::vector<std::pair<std::uint32_t, int>>> edges;
    for (std::uint32_t f = 0; f < mesh.faces.size(); ++f)
        for (int k = 0; k < 3; ++k) {
            const glm::vec3 &p = mesh.faces[f].p[static_cast<std::size_t>(k)],
                            &q = mesh.faces[f].p[static_cast<std::size_t>((k + 1) % 3)];
            Corner a{p.x, p.y, p.z}, b{q.x, q.y, q.z};
            if (b < a) std::swap(a, b);
            edges[{a, b}].emplace_back(f, k);
        }
    const double cosCrease = std::cos(creaseDegrees * kPi / 180.0);
    std::vector<SeamPoint> points;
    std::uint32_t seams = 0;
    for (const auto& [key, sides] : edges) {
        if (sides.size() != 2) continue;  // a border, or three or more faces at one edge
        const auto [f, k] = sides[0];
        const auto [g, m] = sides[1];
        if (glm::dot(mesh.faces[f].normal, mesh.faces[g].normal) < cosCrease) continue;  // a crease
        // f's corners k, k + 1 and the same positions in g (g lists them the other way round
        // when both faces face the same side).
        const glm::dvec2 fa = layout.texels[f][static_cast<std::size_t>(k)],
                         fb = layout.texels[f][static_cast<std::size_t>((k + 1) % 3)];
        glm::dvec2 ga = layout.texels[g][static_cast<std::size_t>(m)],
                   gb = layout.texels[g][static_cast<std::size_t>((m + 1) % 3)];
        if (mesh.faces[g].p[static_cast<std::size_t>(m)] != mesh.faces[f].p[static_cast<std::size_t>(k)])
            std::swap(ga, gb);
        if (layout.pageOf[f] == layout.pageOf[g] && fa == ga && fb == gb) continue;  // one chart
        const double texels = std::max(glm::length(fb - fa), glm::length(gb - ga));
        const int count = std::max(2, static_cast<int>(std::ceil(2.0 * texels)));
        for (int s = 0; s < count; ++s) {
            const double t = (s + 0.5) / count;
            points.push_back({seams, layout.pageOf[f], layout.pageOf[g], fa + t * (fb - fa), ga + t * (gb - ga),
                              mesh.faces[f].material == mesh.faces[g].material});
        }
        ++seams;
    }
    return points;
}

namespace {

// Least squares on one field (irradiance or radiance) of the pages along `points`:
// min |C x|^2 + sum_k lambda_k (x_k - x0_k)^2, C's rows the differences of the two sides' bilinear
// lookups, x the texels they read. Texels that hold surface keep near their value (lambda 0.1
// against a seam point's weight of 1); gutter texels are nearly free (1e-3).
void stitchField(BakedLightmap& lightmap, const std::vector<SeamPoint>& points,
                 std::vector<glm::vec3> LightmapPage::*field) {
    if (points.empty()) return;
    const std::uint32_t size = lightmap.size;
    const std::uint64_t perPage = std::uint64_t{size} * size;
    // Unknowns: the texels the lookups read, numbered as first met.
    std::map<std::uint64_t, int> unknown;
    std::vector<std::uint64_t> texelOf;
    std::vector<Eigen::Triplet<double>> rows;
    for (std::size_t r = 0; r < points.size(); ++r) {
        const SeamPoint& p = points[r];
        for (int side = 0; side < 2; ++side) {
            const Taps taps = bilinearTaps(size, side == 0 ? p.a : p.b);
            const std::uint64_t page = side == 0 ? p.pageA : p.pageB;
            for (std::size_t k = 0; k < 4; ++k) {
                const std::uint64_t texel = page * perPage + taps.texel[k];
                const auto found = unknown.emplace(texel, static_cast<int>(texelOf.size()));
                if (found.second) texelOf.push_back(texel);
                rows.emplace_back(static_cast<int>(r), found.first->second, (side == 0 ? 1.0 : -1.0) * taps.weight[k]);
            }
        }
    }
    const auto n = static_cast<Eigen::Index>(texelOf.size());
    Eigen::SparseMatrix<double> c(static_cast<Eigen::Index>(points.size()), n);
    c.setFromTriplets(rows.begin(), rows.end());  // duplicates (a texel on both sides) add up
    Eigen::VectorXd lambda(n);
    for (Eigen::Index i = 0; i < n; ++i) {
        const std::uint64_t texel = texelOf[static_cast<std::size_t>(i)];
        lambda[i] = lightmap.pages[texel / perPage].area[texel % perPage] > 0.0 ? 0.1 : 1e-3;
    }
    Eigen::SparseMatrix<double> a = c.transpose() * c;
    for (Eigen::Index i = 0; i < n; ++i) a.coeffRef(i, i) += lambda[i];
    // Factored once (sparse Cholesky, fill-reducing order) for the three channels: the seams
    // couple only the few texels around each, so the factor stays sparse. Conjugate gradients
    // per channel on this system (ill conditioned by the gutter texels' weight of 1e-3) made the
    // engine model's lightmap stage 2.5 times as long at 1 sample per texel.
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver;
    solver.compute(a);
    if (solver.info() != Eigen::Success) throw RuntimeFailure("lightmap seams: the stitching system did not factor");
    for (int channel = 0; channel < 3; ++channel) {
        auto value = [&](std::uint64_t texel) -> float& {
            return (lightmap.pages[texel / perPage].*field)[texel % perPage][channel];
        };
        Eigen::VectorXd x0(n);
        for (Eigen::Index i = 0; i < n; ++i) x0[i] = value(texelOf[static_cast<std::size_t>(i)]);
        const Eigen::VectorXd x = solver.solve(lambda.cwiseProduct(x0));
        for (Eigen::Index i = 0; i < n; ++i)  // light is not negative
            value(texelOf[static_cast<std::size_t>(i)]) = static_cast<float>(std::max(0.0, x[i]));
    }
}

}  // namespace

SeamReport stitchSeams(BakedLightmap& lightmap, const LightmapLayout& layout, const Mesh& mesh, double creaseDegrees) {
    const std::vector<SeamPoint> points = seamPoints(layout, mesh, creaseDegrees);
    SeamReport report;
    report.samples = points.size();
    if (points.empty()) return report;
    auto mismatch = [&]() {
        double sum = 0.0;
        for (const SeamPoint& p : points) {
            const double d = luminance(bilinear(lightmap.pages[p.pageA].irradiance, lightmap.size, p.a)) -
                             luminance(bilinear(lightmap.pages[p.pageB].irradiance, lightmap.size, p.b));
            sum += d * d;
        }
        return std::sqrt(sum / static_cast<double>(points.size()));
    };
    report.mismatchBefore = mismatch();
    // The irradiance is continuous across every seam; the radiance only where the material is
    // the same on both sides (rho, Le and their textures may change where it is not).
    stitchField(lightmap, points, &LightmapPage::irradiance);
    std::vector<SeamPoint> sameMaterial;
    for (const SeamPoint& p : points)
        if (p.sameMaterial) sameMaterial.push_back(p);
    stitchField(lightmap, sameMaterial, &LightmapPage::radiance);
    report.mismatchAfter = mismatch();
    report.edges = std::uint64_t{points.back().edge} + 1;
    return report;
}

}  // namespace rad
