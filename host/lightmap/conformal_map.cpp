#include "lightmap/conformal_map.h"

#include <cmath>
#include <cstdint>
#include <map>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <glm/geometric.hpp>

namespace rad {
namespace {

using Triangle = std::array<glm::dvec3, 3>;
using Flat = std::array<glm::dvec2, 3>;

// The chart's vertices, one per position, and each triangle's corners among them.
struct WeldedChart {
    std::vector<glm::dvec3> position;
    std::vector<std::array<std::uint32_t, 3>> corner;
};

WeldedChart weld(const std::vector<Triangle>& triangles) {
    WeldedChart chart;
    std::map<std::array<double, 3>, std::uint32_t> index;
    for (const Triangle& t : triangles) {
        std::array<std::uint32_t, 3> c{};
        for (std::size_t k = 0; k < 3; ++k) {
            const auto found = index.emplace(std::array<double, 3>{t[k].x, t[k].y, t[k].z},
                                             static_cast<std::uint32_t>(chart.position.size()));
            if (found.second) chart.position.push_back(t[k]);
            c[k] = found.first->second;
        }
        chart.corner.push_back(c);
    }
    return chart;
}

// Two vertices far apart, to pin: the first and last along the longer axis of the chart's
// projection onto the plane of its mean normal, with their projected positions.
struct Pins {
    std::uint32_t vertex[2] = {0, 0};
    glm::dvec2 at[2];
};

Pins choosePins(const WeldedChart& chart) {
    glm::dvec3 normal(0.0);
    for (const auto& c : chart.corner)
        normal += glm::cross(chart.position[c[1]] - chart.position[c[0]], chart.position[c[2]] - chart.position[c[0]]);
    const double length = glm::length(normal);
    normal = length > 0.0 ? normal / length : glm::dvec3(0.0, 0.0, 1.0);
    const glm::dvec3 a = std::fabs(normal.x) < 0.9 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 1.0, 0.0);
    const glm::dvec3 u = glm::normalize(glm::cross(a, normal)), v = glm::cross(normal, u);
    const glm::dvec3 origin = chart.position[0];
    std::vector<glm::dvec2> flat(chart.position.size());
    glm::dvec2 lo(INFINITY), hi(-INFINITY);
    for (std::size_t i = 0; i < flat.size(); ++i) {
        const glm::dvec3 d = chart.position[i] - origin;
        flat[i] = {glm::dot(d, u), glm::dot(d, v)};
        lo = glm::min(lo, flat[i]);
        hi = glm::max(hi, flat[i]);
    }
    const int axis = hi.x - lo.x >= hi.y - lo.y ? 0 : 1;
    Pins pins;
    for (std::uint32_t i = 0; i < flat.size(); ++i) {
        if (flat[i][axis] < flat[pins.vertex[0]][axis]) pins.vertex[0] = i;
        if (flat[i][axis] > flat[pins.vertex[1]][axis]) pins.vertex[1] = i;
    }
    pins.at[0] = flat[pins.vertex[0]];
    pins.at[1] = flat[pins.vertex[1]];
    return pins;
}

}  // namespace

std::optional<std::vector<Flat>> conformalMap(const std::vector<Triangle>& triangles) {
    if (triangles.empty()) return std::nullopt;
    const WeldedChart chart = weld(triangles);
    const Pins pins = choosePins(chart);
    if (pins.vertex[0] == pins.vertex[1]) return std::nullopt;
    // Unknowns: u of each free vertex, then v of each.
    const std::uint32_t vertices = static_cast<std::uint32_t>(chart.position.size());
    std::vector<int> column(vertices, -1);
    int free = 0;
    for (std::uint32_t i = 0; i < vertices; ++i)
        if (i != pins.vertex[0] && i != pins.vertex[1]) column[i] = free++;
    std::vector<Eigen::Triplet<double>> entries;
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(2 * static_cast<Eigen::Index>(triangles.size()));
    double surface = 0.0;
    for (std::size_t t = 0; t < triangles.size(); ++t) {
        const auto& c = chart.corner[t];
        const glm::dvec3 p0 = chart.position[c[0]], e = chart.position[c[1]] - p0, f = chart.position[c[2]] - p0;
        const glm::dvec3 n = glm::cross(e, f);
        const double twiceArea = glm::length(n);
        if (!(twiceArea > 0.0) || !std::isfinite(twiceArea)) continue;
        surface += 0.5 * twiceArea;
        // The triangle in its own plane, counter-clockwise: q0 = 0, q1 on the x axis.
        const glm::dvec3 x = glm::normalize(e), y = glm::cross(n / twiceArea, x);
        const glm::dvec2 q[3] = {{0.0, 0.0}, {glm::length(e), 0.0}, {glm::dot(f, x), glm::dot(f, y)}};
        // Gradient of corner j's hat function: the opposite edge turned a quarter, over 2A; rows
        // scaled by sqrt(A) so that each triangle's squared residual is its area's share.
        const double weight = std::sqrt(0.5 * twiceArea) / twiceArea;
        const auto row = static_cast<int>(2 * t);
        for (int j = 0; j < 3; ++j) {
            const glm::dvec2 edge = q[(j + 2) % 3] - q[(j + 1) % 3];
            const double gx = -edge.y * weight, gy = edge.x * weight;
            // Cauchy-Riemann: du/dx - dv/dy = 0 and du/dy + dv/dx = 0.
            const double cu[2] = {gx, gy}, cv[2] = {-gy, gx};
            const std::uint32_t vertex = c[static_cast<std::size_t>(j)];
            for (int r = 0; r < 2; ++r) {
                if (column[vertex] >= 0) {
                    entries.emplace_back(row + r, column[vertex], cu[r]);
                    entries.emplace_back(row + r, free + column[vertex], cv[r]);
                } else {
                    const glm::dvec2 pinned = pins.at[vertex == pins.vertex[0] ? 0 : 1];
                    rhs[row + r] -= cu[r] * pinned.x + cv[r] * pinned.y;
                }
            }
        }
    }
    if (!(surface > 0.0)) return std::nullopt;
    std::vector<glm::dvec2> uv(vertices);
    uv[pins.vertex[0]] = pins.at[0];
    uv[pins.vertex[1]] = pins.at[1];
    if (free > 0) {
        Eigen::SparseMatrix<double> m(rhs.size(), 2 * free);
        m.setFromTriplets(entries.begin(), entries.end());
        const Eigen::SparseMatrix<double> normal = m.transpose() * m;
        Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(normal);
        if (solver.info() != Eigen::Success) return std::nullopt;
        const Eigen::VectorXd solution = solver.solve(m.transpose() * rhs);
        if (solver.info() != Eigen::Success) return std::nullopt;
        for (std::uint32_t i = 0; i < vertices; ++i)
            if (column[i] >= 0) uv[i] = {solution[column[i]], solution[free + column[i]]};
    }
    std::vector<Flat> out(triangles.size());
    double flat = 0.0;
    for (std::size_t t = 0; t < triangles.size(); ++t) {
        for (std::size_t k = 0; k < 3; ++k) out[t][k] = uv[chart.corner[t][k]];
        const Flat& g = out[t];
        flat += 0.5 * ((g[1].x - g[0].x) * (g[2].y - g[0].y) - (g[2].x - g[0].x) * (g[1].y - g[0].y));
    }
    if (!(flat > 0.0) || !std::isfinite(flat)) return std::nullopt;
    const double scale = std::sqrt(surface / flat);
    for (Flat& g : out)
        for (glm::dvec2& p : g) {
            p *= scale;
            if (!std::isfinite(p.x) || !std::isfinite(p.y)) return std::nullopt;
        }
    return out;
}

}  // namespace rad
