#include "lightmap/chart_atlas.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <unordered_map>

#include <glm/geometric.hpp>

#include "util/error.h"

namespace rad {
namespace {

constexpr double kPi = 3.14159265358979323846;

using Triangle = std::array<glm::dvec3, 3>;
using Flat = std::array<glm::dvec2, 3>;

// Triangles that share an edge (the same two vertex positions, in either order); a triangle
// with no normal (degenerate, or not finite: no order of its coordinates) has none.
std::vector<std::vector<std::uint32_t>> edgeNeighbours(const std::vector<Triangle>& triangles,
                                                       const std::vector<glm::dvec3>& normal) {
    using Key = std::array<double, 6>;
    std::map<Key, std::vector<std::uint32_t>> byEdge;
    auto key = [](const glm::dvec3& a, const glm::dvec3& b) {
        const bool swap = std::tie(b.x, b.y, b.z) < std::tie(a.x, a.y, a.z);
        const glm::dvec3& p = swap ? b : a;
        const glm::dvec3& q = swap ? a : b;
        return Key{p.x, p.y, p.z, q.x, q.y, q.z};
    };
    for (std::uint32_t t = 0; t < triangles.size(); ++t)
        if (normal[t] != glm::dvec3(0.0))
            for (int e = 0; e < 3; ++e) byEdge[key(triangles[t][e], triangles[t][(e + 1) % 3])].push_back(t);
    std::vector<std::vector<std::uint32_t>> neighbours(triangles.size());
    for (std::uint32_t t = 0; t < triangles.size(); ++t) {
        if (normal[t] == glm::dvec3(0.0)) continue;
        for (int e = 0; e < 3; ++e)
            for (std::uint32_t other : byEdge[key(triangles[t][e], triangles[t][(e + 1) % 3])])
                if (other != t) neighbours[t].push_back(other);
        std::sort(neighbours[t].begin(), neighbours[t].end());
        neighbours[t].erase(std::unique(neighbours[t].begin(), neighbours[t].end()), neighbours[t].end());
    }
    return neighbours;
}

// Unit normal (zero for a degenerate or non-finite triangle) and area.
glm::dvec3 unitNormal(const Triangle& t, double* area) {
    const glm::dvec3 n = glm::cross(t[1] - t[0], t[2] - t[0]);
    const double length = glm::length(n);
    *area = 0.5 * length;
    if (!(length > 0.0) || !std::isfinite(length)) {
        *area = 0.0;
        return glm::dvec3(0.0);
    }
    return n / length;
}

double flatArea(const Flat& f) {
    return 0.5 * std::fabs((f[1].x - f[0].x) * (f[2].y - f[0].y) - (f[2].x - f[0].x) * (f[1].y - f[0].y));
}

// Whether the interiors of two flat triangles overlap: no edge normal of either separates
// them. Touching along an edge or at a point is not overlap (neighbours share edges).
bool interiorsOverlap(const Flat& a, const Flat& b, double eps) {
    for (const Flat* t : {&a, &b})
        for (int e = 0; e < 3; ++e) {
            const glm::dvec2 d = (*t)[(e + 1) % 3] - (*t)[e];
            const glm::dvec2 axis(-d.y, d.x);
            double aLo = std::numeric_limits<double>::max(), aHi = -aLo, bLo = aLo, bHi = -aLo;
            for (int k = 0; k < 3; ++k) {
                const double pa = glm::dot(axis, a[k]), pb = glm::dot(axis, b[k]);
                aLo = std::min(aLo, pa), aHi = std::max(aHi, pa);
                bLo = std::min(bLo, pb), bHi = std::max(bHi, pb);
            }
            const double scale = glm::length(axis);
            if (std::min(aHi, bHi) - std::max(aLo, bLo) <= eps * scale) return false;
        }
    return true;
}

struct Bounds2 {
    glm::dvec2 lo{std::numeric_limits<double>::max()}, hi{-std::numeric_limits<double>::max()};
    void extend(const Flat& f) {
        for (const glm::dvec2& p : f) lo = glm::min(lo, p), hi = glm::max(hi, p);
    }
    Bounds2 with(const Flat& f) const {
        Bounds2 b = *this;
        b.extend(f);
        return b;
    }
    // Texels the box spans along each axis (at least one).
    double texelsWide() const { return std::max(1.0, std::ceil(hi.x - lo.x)); }
    double texelsHigh() const { return std::max(1.0, std::ceil(hi.y - lo.y)); }
};

// The chart's flat triangles, hashed by the grid cells their boxes touch, to test a newcomer
// against only those near it.
class FlatIndex {
public:
    explicit FlatIndex(double cell) : cell_(cell) {}

    bool overlapsAny(const Flat& f, const std::vector<Flat>& flats, double eps) const {
        bool found = false;
        forCells(f, [&](std::int64_t key) {
            const auto it = cells_.find(key);
            if (it == cells_.end() || found) return;
            for (std::uint32_t k : it->second)
                if (interiorsOverlap(f, flats[k], eps)) {
                    found = true;
                    return;
                }
        });
        return found;
    }

    // Every entry in the cells f's box touches (with repeats).
    void collect(const Flat& f, std::vector<std::uint32_t>* out) const {
        forCells(f, [&](std::int64_t key) {
            const auto it = cells_.find(key);
            if (it != cells_.end()) out->insert(out->end(), it->second.begin(), it->second.end());
        });
    }

    void add(const Flat& f, std::uint32_t k) {
        forCells(f, [&](std::int64_t key) { cells_[key].push_back(k); });
    }

private:
    template <class Visit>
    void forCells(const Flat& f, Visit visit) const {
        Bounds2 b;
        b.extend(f);
        const auto x0 = static_cast<std::int64_t>(std::floor(b.lo.x / cell_)),
                   x1 = static_cast<std::int64_t>(std::floor(b.hi.x / cell_));
        const auto y0 = static_cast<std::int64_t>(std::floor(b.lo.y / cell_)),
                   y1 = static_cast<std::int64_t>(std::floor(b.hi.y / cell_));
        for (std::int64_t y = y0; y <= y1; ++y)
            for (std::int64_t x = x0; x <= x1; ++x) visit(y * 2'000'003 + x);
    }

    double cell_;
    std::unordered_map<std::int64_t, std::vector<std::uint32_t>> cells_;
};

// An orthonormal pair spanning the plane of unit normal n (any, for a zero normal).
void planeAxes(const glm::dvec3& n, glm::dvec3* u, glm::dvec3* v) {
    if (n == glm::dvec3(0.0)) {
        *u = {1.0, 0.0, 0.0};
        *v = {0.0, 1.0, 0.0};
        return;
    }
    const glm::dvec3 a = std::fabs(n.x) < 0.9 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 1.0, 0.0);
    *u = glm::normalize(glm::cross(a, n));
    *v = glm::cross(n, *u);
}

Flat project(const Triangle& t, const glm::dvec3& u, const glm::dvec3& v, double texelSize) {
    Flat f;
    for (int k = 0; k < 3; ++k) f[k] = glm::dvec2(glm::dot(t[k], u), glm::dot(t[k], v)) / texelSize;
    return f;
}

std::string metres(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", x);
    return text;
}

// The options' own limits, whatever the triangles.
void checkAtlasOptions(const AtlasOptions& options) {
    if (!(options.texelSize > 0.0) || !std::isfinite(options.texelSize))
        throw InputError("the lightmap's texel size must be a positive number of metres (got " +
                         metres(options.texelSize) + ")");
    if (options.pageSize < 2 * options.gutter + 1)
        throw InputError("a lightmap page of " + std::to_string(options.pageSize) +
                         " texels has no room inside a gutter of " + std::to_string(options.gutter));
    if (!(options.coneDegrees >= 0.0 && options.coneDegrees < 90.0))
        throw InputError("a chart's cone must be at least 0 and under 90 degrees");
}

// The triangles' unit normals and areas, and who shares an edge with whom: what growing the
// charts reads.
struct TriangleFacts {
    std::vector<double> area;
    std::vector<glm::dvec3> normal;
    std::vector<std::vector<std::uint32_t>> neighbours;
};

TriangleFacts triangleFacts(const std::vector<Triangle>& triangles) {
    TriangleFacts facts;
    facts.area.resize(triangles.size());
    facts.normal.resize(triangles.size());
    for (std::size_t t = 0; t < triangles.size(); ++t) facts.normal[t] = unitNormal(triangles[t], &facts.area[t]);
    facts.neighbours = edgeNeighbours(triangles, facts.normal);
    return facts;
}

// Phase 1: the charts, each grown breadth-first from the first triangle not yet in one, with
// their triangles' texel coordinates relative to the chart's corner; or the first triangle
// larger than a page on its own.
std::optional<OversizedTriangle> growCharts(const std::vector<Triangle>& triangles, const TriangleFacts& facts,
                                            const AtlasOptions& options, Atlas& atlas) {
    const double room = options.pageSize - 2.0 * options.gutter;  // texels a chart may span
    const double cosCone = std::cos(options.coneDegrees * kPi / 180.0);
    const std::vector<glm::dvec3>& normal = facts.normal;
    std::vector<bool> taken(triangles.size(), false);
    for (std::uint32_t seed = 0; seed < triangles.size(); ++seed) {
        if (taken[seed]) continue;
        AtlasChart chart;
        chart.normal = normal[seed];
        glm::dvec3 u, v;
        planeAxes(chart.normal, &u, &v);
        // A triangle without a normal has no area to light: a point of its own.
        const Flat first = chart.normal == glm::dvec3(0.0) ? Flat{} : project(triangles[seed], u, v, options.texelSize);
        Bounds2 box;
        box.extend(first);
        if (!(box.hi.x - box.lo.x <= room && box.hi.y - box.lo.y <= room)) {
            const double span = std::max(box.hi.x - box.lo.x, box.hi.y - box.lo.y);
            return OversizedTriangle{seed, span, options.texelSize * span / room * 1.01};
        }
        std::vector<Flat> flats{first};
        std::vector<std::uint32_t> members{seed};
        // Cells about twice the first triangle's size: a newcomer meets a few of its neighbours.
        FlatIndex index(std::max(1.0, 2.0 * std::max(box.hi.x - box.lo.x, box.hi.y - box.lo.y)));
        index.add(first, 0);
        taken[seed] = true;
        // Touching, not overlapping, within rounding of the coordinates' size.
        const double eps =
            1e-9 * std::max({1.0, std::fabs(box.lo.x), std::fabs(box.lo.y), std::fabs(box.hi.x), std::fabs(box.hi.y)});
        std::deque<std::uint32_t> frontier{seed};
        while (!frontier.empty() && chart.normal != glm::dvec3(0.0)) {
            const std::uint32_t from = frontier.front();
            frontier.pop_front();
            for (std::uint32_t t : facts.neighbours[from]) {
                if (taken[t] || normal[t] == glm::dvec3(0.0) || glm::dot(normal[t], chart.normal) < cosCone) continue;
                const Flat f = project(triangles[t], u, v, options.texelSize);
                const Bounds2 grown = box.with(f);
                if (grown.hi.x - grown.lo.x > room || grown.hi.y - grown.lo.y > room) continue;
                if (index.overlapsAny(f, flats, eps)) continue;
                index.add(f, static_cast<std::uint32_t>(flats.size()));
                flats.push_back(f);
                members.push_back(t);
                box = grown;
                taken[t] = true;
                frontier.push_back(t);
            }
        }
        const auto c = static_cast<std::uint32_t>(atlas.charts.size());
        for (std::size_t k = 0; k < members.size(); ++k) {
            atlas.chartOf[members[k]] = c;
            for (int corner = 0; corner < 3; ++corner) atlas.texels[members[k]][corner] = flats[k][corner] - box.lo;
        }
        std::sort(members.begin(), members.end());
        chart.triangles = std::move(members);
        chart.width = static_cast<std::uint32_t>(box.texelsWide());
        chart.height = static_cast<std::uint32_t>(box.texelsHigh());
        atlas.charts.push_back(std::move(chart));
    }
    return std::nullopt;
}

// Phase 2: shelf packing, tallest charts first: each takes a box of its size plus a gutter on
// every side, so two charts lie at least two gutters apart and one gutter from a page's edge.
void packCharts(Atlas& atlas) {
    std::vector<std::uint32_t> order(atlas.charts.size());
    for (std::uint32_t c = 0; c < order.size(); ++c) order[c] = c;
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
        const AtlasChart &p = atlas.charts[a], &q = atlas.charts[b];
        return std::tie(q.height, q.width, a) < std::tie(p.height, p.width, b);
    });
    const std::uint32_t g = atlas.gutter, side = atlas.pageSize;
    std::uint32_t page = 0, shelfY = 0, shelfHeight = 0, cursor = 0;
    bool any = false;
    for (std::uint32_t c : order) {
        AtlasChart& chart = atlas.charts[c];
        const std::uint32_t w = chart.width + 2 * g, h = chart.height + 2 * g;
        if (cursor + w > side) {  // the next shelf
            shelfY += shelfHeight;
            shelfHeight = 0;
            cursor = 0;
        }
        if (shelfY + h > side) {  // the next page
            ++page;
            shelfY = 0;
            shelfHeight = 0;
            cursor = 0;
        }
        chart.page = page;
        chart.x = cursor + g;
        chart.y = shelfY + g;
        cursor += w;
        shelfHeight = std::max(shelfHeight, h);
        any = true;
    }
    atlas.pages = any ? page + 1 : 0;
}

// Phase 3: each triangle's texel coordinates moved to where its chart was packed, and what the
// atlas makes of the pages' texels and the surface.
void placeTexels(const TriangleFacts& facts, Atlas& atlas) {
    double used = 0.0;
    for (std::size_t t = 0; t < atlas.texels.size(); ++t) {
        const AtlasChart& chart = atlas.charts[atlas.chartOf[t]];
        for (glm::dvec2& p : atlas.texels[t]) p += glm::dvec2(chart.x, chart.y);
        const double flat = flatArea(atlas.texels[t]);
        used += flat;
        if (flat > 0.0 && facts.area[t] > 0.0)
            atlas.largestStretch =
                std::max(atlas.largestStretch, facts.area[t] / (flat * atlas.texelSize * atlas.texelSize));
    }
    const double side = atlas.pageSize;
    if (atlas.pages > 0) atlas.areaUse = used / (static_cast<double>(atlas.pages) * side * side);
}

}  // namespace

AtlasAttempt tryAtlas(const std::vector<Triangle>& triangles, const AtlasOptions& options) {
    checkAtlasOptions(options);
    Atlas atlas;
    atlas.texelSize = options.texelSize;
    atlas.pageSize = options.pageSize;
    atlas.gutter = options.gutter;
    atlas.chartOf.assign(triangles.size(), 0);
    atlas.texels.resize(triangles.size());
    const TriangleFacts facts = triangleFacts(triangles);
    AtlasAttempt attempt;
    if (const std::optional<OversizedTriangle> oversized = growCharts(triangles, facts, options, atlas)) {
        attempt.oversized = *oversized;
        return attempt;
    }
    packCharts(atlas);
    placeTexels(facts, atlas);
    attempt.atlas = std::move(atlas);
    return attempt;
}

Atlas buildAtlas(const std::vector<Triangle>& triangles, const AtlasOptions& options) {
    AtlasAttempt attempt = tryAtlas(triangles, options);
    if (!attempt.atlas) {
        const OversizedTriangle& o = attempt.oversized;
        throw InputError("triangle " + std::to_string(o.triangle) + " spans " + metres(o.span) +
                         " texels at a texel size of " + metres(options.texelSize) + " m, more than a page of " +
                         std::to_string(options.pageSize) + " texels holds inside its gutter; use a texel size of " +
                         metres(o.fittingTexelSize) + " m or more, or larger pages");
    }
    return std::move(*attempt.atlas);
}

UvLayoutCheck checkUvLayout(const std::vector<Flat>& uv, std::size_t maxExamples) {
    UvLayoutCheck check;
    // Cells about the size of the median triangle's box, so each triangle meets a few others.
    std::vector<double> sizes;
    std::vector<bool> solid(uv.size(), false);
    Bounds2 all;
    for (std::size_t t = 0; t < uv.size(); ++t) {
        const Flat& f = uv[t];
        bool finite = true;
        for (const glm::dvec2& p : f) finite = finite && std::isfinite(p.x) && std::isfinite(p.y);
        if (!finite || !(flatArea(f) > 0.0)) {
            ++check.degenerate;
            continue;
        }
        solid[t] = true;
        Bounds2 b;
        b.extend(f);
        all.extend(f);
        sizes.push_back(std::max(b.hi.x - b.lo.x, b.hi.y - b.lo.y));
    }
    if (sizes.empty()) return check;
    std::nth_element(sizes.begin(), sizes.begin() + sizes.size() / 2, sizes.end());
    // No more than 1024 cells across the whole layout, however far one coordinate strays.
    const double span = std::max(all.hi.x - all.lo.x, all.hi.y - all.lo.y);
    FlatIndex index(std::max({sizes[sizes.size() / 2], span / 1024.0, 1e-12}));
    const double eps = 1e-9;  // UVs are of order 1
    for (std::size_t t = 0; t < uv.size(); ++t) {
        if (!solid[t]) continue;
        // Every earlier triangle in the cells this one touches, each pair once.
        std::vector<std::uint32_t> near;
        index.collect(uv[t], &near);
        std::sort(near.begin(), near.end());
        near.erase(std::unique(near.begin(), near.end()), near.end());
        for (std::uint32_t other : near)
            if (interiorsOverlap(uv[other], uv[t], eps)) {
                ++check.overlappingPairs;
                if (check.examples.size() < maxExamples)
                    check.examples.push_back({other, static_cast<std::uint32_t>(t)});
            }
        index.add(uv[t], static_cast<std::uint32_t>(t));
    }
    return check;
}

}  // namespace rad
