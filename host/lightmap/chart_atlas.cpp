#include "lightmap/chart_atlas.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <queue>
#include <string>
#include <tuple>
#include <unordered_map>

#include <Eigen/Dense>
#include <glm/geometric.hpp>

#include "lightmap/chart_packing.h"
#include "lightmap/conformal_map.h"
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
}

void checkChartOptions(const ChartOptions& options) {
    if (!(options.coneDegrees > 0.0 && options.coneDegrees < 90.0))
        throw InputError("a lightmap chart's cone must be above 0 and under 90 degrees");
    if (!(options.creaseDegrees >= 0.0 && options.creaseDegrees <= 180.0))
        throw InputError("a lightmap chart's crease angle must be 0 to 180 degrees");
    if (!(options.stretchLimit >= 1.0) || !std::isfinite(options.stretchLimit))
        throw InputError("a lightmap chart's stretch limit must be 1 or more");
    if (!(options.attachArea >= 0.0 && options.attachExtent >= 0.0) || !std::isfinite(options.attachArea) ||
        !std::isfinite(options.attachExtent))
        throw InputError("a lightmap chart's attach area and extent must be 0 or more");
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

double signedArea(const Flat& f) {
    return 0.5 * ((f[1].x - f[0].x) * (f[2].y - f[0].y) - (f[2].x - f[0].x) * (f[1].y - f[0].y));
}

// Touching, not overlapping, within rounding of the coordinates' size.
double touchingTolerance(const Bounds2& box) {
    return 1e-9 * std::max({1.0, std::fabs(box.lo.x), std::fabs(box.lo.y), std::fabs(box.hi.x), std::fabs(box.hi.y)});
}

// Charts laid flat by projection onto their first triangle's plane, in units of `unit` metres.
struct ProjectedChart {
    std::vector<std::uint32_t> members;  // in the order they joined
    std::vector<Flat> flats;
    Bounds2 box;
};

constexpr double kProjectionConeDegrees = 15.0;

// Charts grown over `subset` (ascending) by projection, each breadth-first from the first
// triangle of the subset not yet in one while the newcomer's normal lies within 15 degrees of
// the first one's, its projection overlaps none of the chart's and the chart stays within `room`
// units a side; or the first triangle larger than `room` on its own. A flat region keeps its
// shape exactly; a gently curved one is compressed along its tilt by at most cos(15 degrees).
std::optional<OversizedTriangle> projectCharts(const std::vector<Triangle>& triangles, const TriangleFacts& facts,
                                               const std::vector<std::uint32_t>& subset, double unit, double room,
                                               std::vector<std::uint8_t>& available,
                                               std::vector<ProjectedChart>* out) {
    const double cosCone = std::cos(kProjectionConeDegrees * kPi / 180.0);
    const std::vector<glm::dvec3>& normal = facts.normal;
    for (std::uint32_t t : subset) available[t] = 1;
    std::optional<OversizedTriangle> oversized;
    for (std::uint32_t seed : subset) {
        if (!available[seed]) continue;
        ProjectedChart chart;
        const glm::dvec3 axis = normal[seed];
        glm::dvec3 u, v;
        planeAxes(axis, &u, &v);
        // A triangle without a normal has no area to light: a point of its own.
        const Flat first = axis == glm::dvec3(0.0) ? Flat{} : project(triangles[seed], u, v, unit);
        chart.box.extend(first);
        if (!(chart.box.hi.x - chart.box.lo.x <= room && chart.box.hi.y - chart.box.lo.y <= room)) {
            const double span = std::max(chart.box.hi.x - chart.box.lo.x, chart.box.hi.y - chart.box.lo.y);
            oversized = OversizedTriangle{seed, span, unit * span / room * 1.01};
            break;
        }
        chart.flats.push_back(first);
        chart.members.push_back(seed);
        // Cells about twice the first triangle's size, so a newcomer meets a few of its
        // neighbours; no fewer than 1/1024 of the room across, so that a tiny first triangle does
        // not put a large newcomer into millions of cells.
        FlatIndex index(std::max({2.0 * std::max(chart.box.hi.x - chart.box.lo.x, chart.box.hi.y - chart.box.lo.y),
                                  room / 1024.0, 1e-300}));
        index.add(first, 0);
        available[seed] = 0;
        const double eps = touchingTolerance(chart.box);
        std::deque<std::uint32_t> frontier{seed};
        while (!frontier.empty() && axis != glm::dvec3(0.0)) {
            const std::uint32_t from = frontier.front();
            frontier.pop_front();
            for (std::uint32_t t : facts.neighbours[from]) {
                if (!available[t] || normal[t] == glm::dvec3(0.0) || glm::dot(normal[t], axis) < cosCone) continue;
                const Flat f = project(triangles[t], u, v, unit);
                const Bounds2 grown = chart.box.with(f);
                if (grown.hi.x - grown.lo.x > room || grown.hi.y - grown.lo.y > room) continue;
                if (index.overlapsAny(f, chart.flats, eps)) continue;
                index.add(f, static_cast<std::uint32_t>(chart.flats.size()));
                chart.flats.push_back(f);
                chart.members.push_back(t);
                chart.box = grown;
                available[t] = 0;
                frontier.push_back(t);
            }
        }
        out->push_back(std::move(chart));
    }
    for (std::uint32_t t : subset) available[t] = 0;
    return oversized;
}

// The convex hull of the points, counter-clockwise (Andrew's monotone chain).
std::vector<glm::dvec2> convexHull(std::vector<glm::dvec2> points) {
    std::sort(points.begin(), points.end(),
              [](const glm::dvec2& a, const glm::dvec2& b) { return std::tie(a.x, a.y) < std::tie(b.x, b.y); });
    points.erase(std::unique(points.begin(), points.end()), points.end());
    if (points.size() < 3) return points;
    auto turn = [](const glm::dvec2& o, const glm::dvec2& a, const glm::dvec2& b) {
        return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
    };
    std::vector<glm::dvec2> hull(2 * points.size());
    std::size_t k = 0;
    for (const glm::dvec2& p : points) {
        while (k >= 2 && turn(hull[k - 2], hull[k - 1], p) <= 0.0) --k;
        hull[k++] = p;
    }
    for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
        while (k >= lower && turn(hull[k - 2], hull[k - 1], points[i]) <= 0.0) --k;
        hull[k++] = points[i];
    }
    hull.resize(k - 1);
    return hull;
}

// The chart turned to the smallest rectangle that holds it (one of its hull's edges lies along a
// side of that rectangle), lying (width >= height), its smallest corner at the origin.
FlatChart settled(std::vector<std::uint32_t> members, std::vector<Flat> corners) {
    std::vector<glm::dvec2> points;
    for (const Flat& f : corners) points.insert(points.end(), f.begin(), f.end());
    const std::vector<glm::dvec2> hull = convexHull(points);
    glm::dvec2 along(1.0, 0.0);
    double best = INFINITY;
    for (std::size_t i = 0; i < hull.size() && hull.size() >= 3; ++i) {
        const glm::dvec2 edge = hull[(i + 1) % hull.size()] - hull[i];
        const double length = glm::length(edge);
        if (!(length > 0.0)) continue;
        const glm::dvec2 d = edge / length;
        double xlo = INFINITY, xhi = -INFINITY, ylo = INFINITY, yhi = -INFINITY;
        for (const glm::dvec2& p : hull) {
            const double x = glm::dot(p, d), y = d.x * p.y - d.y * p.x;
            xlo = std::min(xlo, x), xhi = std::max(xhi, x), ylo = std::min(ylo, y), yhi = std::max(yhi, y);
        }
        const double area = (xhi - xlo) * (yhi - ylo);
        if (area < best) {
            best = area;
            along = (xhi - xlo) >= (yhi - ylo) ? d : glm::dvec2(-d.y, d.x);
        }
    }
    // A rotation taking `along` to +x keeps every triangle's orientation.
    Bounds2 box;
    for (Flat& f : corners) {
        for (glm::dvec2& p : f) p = {glm::dot(p, along), along.x * p.y - along.y * p.x};
        box.extend(f);
    }
    FlatChart chart;
    for (Flat& f : corners)
        for (glm::dvec2& p : f) p -= box.lo;
    chart.extent = box.hi - box.lo;
    if (corners.size() == 1 && box.lo == box.hi) chart.extent = glm::dvec2(0.0);
    // Ascending triangles, their corners with them.
    std::vector<std::size_t> order(members.size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return members[a] < members[b]; });
    for (std::size_t k : order) {
        chart.triangles.push_back(members[k]);
        chart.corners.push_back(corners[k]);
    }
    return chart;
}

// Whether a chart's flat layout keeps every triangle the right way round, within the stretch
// limit of its share of the surface, and off every other.
bool acceptable(const std::vector<std::uint32_t>& members, const std::vector<Flat>& flat, const TriangleFacts& facts,
                double stretchLimit) {
    Bounds2 all;
    std::vector<double> sizes;
    for (std::size_t k = 0; k < flat.size(); ++k) {
        const double a = signedArea(flat[k]), surface = facts.area[members[k]];
        if (!(a > 0.0)) return false;
        if (!(a <= stretchLimit * surface && a * stretchLimit >= surface)) return false;
        Bounds2 b;
        b.extend(flat[k]);
        all.extend(flat[k]);
        sizes.push_back(std::max(b.hi.x - b.lo.x, b.hi.y - b.lo.y));
    }
    std::nth_element(sizes.begin(), sizes.begin() + static_cast<std::ptrdiff_t>(sizes.size() / 2), sizes.end());
    const double span = std::max(all.hi.x - all.lo.x, all.hi.y - all.lo.y);
    FlatIndex index(std::max({2.0 * sizes[sizes.size() / 2], span / 1024.0, 1e-300}));
    const double eps = touchingTolerance(all);
    for (std::size_t k = 0; k < flat.size(); ++k) {
        if (index.overlapsAny(flat[k], flat, eps)) return false;
        index.add(flat[k], static_cast<std::uint32_t>(k));
    }
    return true;
}

// Phase 1b: charts under the attach area joined to neighbours they unfold onto (ChartOptions).
// Smallest by area first, each chart is tried against each neighbour of its group about each
// of the kHinges longest edges they share: the turn, shift and scale (within kHingeScale of 1)
// that lays the hinge on the neighbour's copy of it. The chart's corners that then land within
// 1 % of the hinge's length (or 1/1000 of the attach area's side) of their vertex's nearest place
// in the neighbour are put there exactly: the two meet there; where they do not, the chart is cut
// there, as along a crease. That must keep every triangle the right way round, within the
// stretch limit and off the chart's others and the neighbour's, the neighbour's box (in its
// frame before it is turned to its smallest rectangle) within the attach extent or its own
// width, and its area within kBoxGrowth of the two boxes' (the packer fills a box's corners only
// with other charts: a chart that sprawls wastes the page). Of the hinges, the one that leaves
// the neighbour's box smallest; of the neighbours, the one whose box grows least (of equals, the
// one sharing the most edge length). A chart that attaches nowhere is not tried again.
class ChartAttacher {
public:
    ChartAttacher(const std::vector<Triangle>& triangles, const std::vector<std::uint32_t>& groups,
                  const ChartOptions& options, const TriangleFacts& facts)
        : triangles_(triangles), groups_(groups), options_(options), facts_(facts),
          chartOf_(triangles.size(), 0), slot_(triangles.size(), 0) {}

    // The charts after attaching; a chart that grew is settled again, the others are kept as
    // they were, in order.
    std::vector<FlatChart> attached(std::vector<FlatChart> charts) {
        charts_ = std::move(charts);
        const std::size_t count = charts_.size();
        area_.assign(count, 0.0);
        box_.assign(count, Bounds2{});
        for (std::uint32_t c = 0; c < count; ++c)
            for (std::uint32_t k = 0; k < charts_[c].triangles.size(); ++k) {
                const std::uint32_t t = charts_[c].triangles[k];
                chartOf_[t] = c, slot_[t] = k;
                area_[c] += facts_.area[t];
                box_[c].extend(charts_[c].corners[k]);
            }
        // Per neighbouring chart of the same group, the length of the edges they share.
        std::vector<std::map<std::uint32_t, double>> shared(count);
        for (std::uint32_t t = 0; t < triangles_.size(); ++t) {
            if (facts_.normal[t] == glm::dvec3(0.0)) continue;
            for (int e = 0; e < 3; ++e) {
                const glm::dvec3 &p = triangles_[t][e], &q = triangles_[t][(e + 1) % 3];
                for (std::uint32_t u : facts_.neighbours[t])
                    if (chartOf_[u] != chartOf_[t] && group(u) == group(t) && hasEdge(u, p, q))
                        shared[chartOf_[t]][chartOf_[u]] += glm::length(q - p);
            }
        }
        using Entry = std::pair<double, std::uint32_t>;
        std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> smallest;
        for (std::uint32_t c = 0; c < count; ++c)
            if (area_[c] > 0.0 && area_[c] < options_.attachArea) smallest.emplace(area_[c], c);
        std::vector<bool> alive(count, true), grew(count, false);
        while (!smallest.empty()) {
            const auto [a, r] = smallest.top();
            smallest.pop();
            if (!alive[r] || a != area_[r]) continue;  // attached already, or an old entry
            // Neighbours by the length shared, longest first (then in order): of equal growths,
            // the one that leaves the fewest edges cut.
            std::vector<std::pair<double, std::uint32_t>> neighbours;
            for (const auto& [n, length] : shared[r]) neighbours.emplace_back(-length, n);
            std::sort(neighbours.begin(), neighbours.end());
            std::optional<Unfolding> best;
            for (const auto& [negativeLength, n] : neighbours) {
                std::optional<Unfolding> way = unfolded(r, n);
                // Growths equal but for rounding are equal: the longer shared edge keeps it.
                if (way && (!best || way->growth < best->growth - 1e-9 * best->boxArea)) best = std::move(way);
            }
            if (!best) continue;
            const std::uint32_t n = best->onto;
            for (std::size_t k = 0; k < best->corners.size(); ++k) {
                const std::uint32_t t = charts_[r].triangles[k];
                chartOf_[t] = n, slot_[t] = static_cast<std::uint32_t>(charts_[n].triangles.size());
                charts_[n].triangles.push_back(t);
                charts_[n].corners.push_back(best->corners[k]);
                box_[n].extend(best->corners[k]);
            }
            for (const auto& [m, length] : shared[r]) {
                const double back = shared[m][r];
                shared[m].erase(r);
                if (m == n) continue;
                shared[m][n] += back;
                shared[n][m] += length;
            }
            shared[n].erase(r);
            shared[r].clear();
            charts_[r] = FlatChart{};
            alive[r] = false;
            grew[n] = true;
            area_[n] += area_[r];
            if (area_[n] < options_.attachArea) smallest.emplace(area_[n], n);
        }
        std::vector<FlatChart> out;
        for (std::uint32_t c = 0; c < count; ++c) {
            if (!alive[c]) continue;
            if (grew[c])
                out.push_back(settled(std::move(charts_[c].triangles), std::move(charts_[c].corners)));
            else
                out.push_back(std::move(charts_[c]));
        }
        return out;
    }

private:
    static constexpr std::size_t kHinges = 8;
    static constexpr double kHingeScale = 1.1;
    static constexpr double kBoxGrowth = 1.25;

    using Places = std::map<std::array<double, 3>, std::vector<glm::dvec2>>;

    struct Unfolding {
        std::uint32_t onto = 0;
        std::vector<Flat> corners;  // the chart's, in onto's layout
        double boxArea = 0.0;       // of onto's box with them
        double growth = 0.0;        // what that adds to onto's box
    };

    std::uint32_t group(std::uint32_t t) const { return groups_.empty() ? 0u : groups_[t]; }

    // Whether triangle u has the edge p-q (either way round).
    bool hasEdge(std::uint32_t u, const glm::dvec3& p, const glm::dvec3& q) const {
        bool hasP = false, hasQ = false;
        for (const glm::dvec3& c : triangles_[u]) hasP = hasP || c == p, hasQ = hasQ || c == q;
        return hasP && hasQ;
    }

    static double areaOf(const Bounds2& b) { return (b.hi.x - b.lo.x) * (b.hi.y - b.lo.y); }
    static double sideOf(const Bounds2& b) { return std::max(b.hi.x - b.lo.x, b.hi.y - b.lo.y); }

    // Chart r laid onto chart n the best way it unfolds onto it, or nothing.
    std::optional<Unfolding> unfolded(std::uint32_t r, std::uint32_t n) const {
        // The edges r shares with n, their ends' places in both layouts; per shared vertex, its
        // places in n.
        struct SharedEdge {
            glm::dvec2 a0, a1, b0, b1;
        };
        std::vector<SharedEdge> edges;
        Places inN;
        const FlatChart& from = charts_[r];
        for (std::size_t k = 0; k < from.triangles.size(); ++k) {
            const std::uint32_t t = from.triangles[k];
            for (int e = 0; e < 3; ++e) {
                const int f = (e + 1) % 3;
                const glm::dvec3 &p = triangles_[t][e], &q = triangles_[t][f];
                for (std::uint32_t u : facts_.neighbours[t]) {
                    if (chartOf_[u] != n || !hasEdge(u, p, q)) continue;
                    const Flat& onto = charts_[n].corners[slot_[u]];
                    SharedEdge edge{from.corners[k][e], from.corners[k][f], {}, {}};
                    for (int j = 0; j < 3; ++j) {
                        if (triangles_[u][j] == p) edge.b0 = onto[j];
                        if (triangles_[u][j] == q) edge.b1 = onto[j];
                    }
                    edges.push_back(edge);
                    inN[{p.x, p.y, p.z}].push_back(edge.b0);
                    inN[{q.x, q.y, q.z}].push_back(edge.b1);
                }
            }
        }
        // The longest first, the first of equals.
        std::stable_sort(edges.begin(), edges.end(), [](const SharedEdge& x, const SharedEdge& y) {
            return glm::length(x.b1 - x.b0) > glm::length(y.b1 - y.b0);
        });
        if (edges.size() > kHinges) edges.resize(kHinges);
        Bounds2 own;
        for (const Flat& f : from.corners) own.extend(f);
        const double limit = kBoxGrowth * (areaOf(box_[n]) + areaOf(own));
        std::optional<Unfolding> best;
        for (const SharedEdge& hinge : edges) {
            const double within = best ? std::min(limit, best->boxArea) : limit;
            std::optional<Unfolding> way = unfoldedAbout(from, n, hinge.a0, hinge.a1, hinge.b0, hinge.b1, inN, within);
            if (way && (!best || way->boxArea < best->boxArea)) best = std::move(way);
        }
        return best;
    }

    // Chart `from` laid onto chart n about the hinge a0-a1 (in from's layout), b0-b1 (in n's),
    // where n's box then stays within `boxLimit` (m^2), or nothing.
    std::optional<Unfolding> unfoldedAbout(const FlatChart& from, std::uint32_t n, glm::dvec2 a0, glm::dvec2 a1,
                                           glm::dvec2 b0, glm::dvec2 b1, const Places& inN, double boxLimit) const {
        const glm::dvec2 da = a1 - a0, db = b1 - b0;
        const double la = glm::length(da), lb = glm::length(db);
        if (!(la > 0.0 && lb > 0.0)) return std::nullopt;
        const double scale = lb / la;
        if (!(scale <= kHingeScale && scale * kHingeScale >= 1.0)) return std::nullopt;
        // Within 1 % of the hinge's length or 1/1000 of the attach area's side, whichever is more.
        const double snap = std::max(0.01 * lb, 1e-3 * std::sqrt(options_.attachArea));
        const double rounding = 1e-9 * lb;
        // The turn and scale taking da to db, about the hinge's middle.
        const double cosine = glm::dot(da, db) / (la * la), sine = (da.x * db.y - da.y * db.x) / (la * la);
        const glm::dvec2 ca = 0.5 * (a0 + a1), cb = 0.5 * (b0 + b1);
        auto move = [&](const glm::dvec2& a) {
            const glm::dvec2 d = a - ca;
            return cb + glm::dvec2(cosine * d.x - sine * d.y, sine * d.x + cosine * d.y);
        };
        Unfolding way;
        way.onto = n;
        way.corners.resize(from.corners.size());
        Bounds2 own;
        bool snapped = false;
        for (std::size_t k = 0; k < from.corners.size(); ++k) {
            Flat& corners = way.corners[k];
            for (int j = 0; j < 3; ++j) {
                const glm::dvec3& p = triangles_[from.triangles[k]][j];
                corners[j] = move(from.corners[k][j]);
                const auto found = inN.find({p.x, p.y, p.z});
                if (found == inN.end()) continue;
                const glm::dvec2* nearest = nullptr;
                for (const glm::dvec2& b : found->second)
                    if (!nearest || glm::length(b - corners[j]) < glm::length(*nearest - corners[j])) nearest = &b;
                const double distance = glm::length(*nearest - corners[j]);
                if (distance > snap) continue;
                snapped = snapped || distance > rounding;
                corners[j] = *nearest;
            }
            const double a = signedArea(corners), surface = facts_.area[from.triangles[k]];
            if (!(a > 0.0 && a <= options_.stretchLimit * surface && a * options_.stretchLimit >= surface))
                return std::nullopt;
            own.extend(corners);
        }
        Bounds2 both = box_[n];
        both.lo = glm::min(both.lo, own.lo), both.hi = glm::max(both.hi, own.hi);
        if (sideOf(both) > std::max(sideOf(box_[n]), options_.attachExtent)) return std::nullopt;
        way.boxArea = areaOf(both);
        if (!(way.boxArea <= boxLimit)) return std::nullopt;
        way.growth = way.boxArea - areaOf(box_[n]);
        // A corner moved onto n's may have put one of the chart's triangles on another.
        if (snapped && !acceptable(from.triangles, way.corners, facts_, options_.stretchLimit)) return std::nullopt;
        // On none of n's triangles.
        std::vector<Bounds2> boxes(way.corners.size());
        for (std::size_t k = 0; k < boxes.size(); ++k) boxes[k].extend(way.corners[k]);
        auto apart = [](const Bounds2& a, const Bounds2& b) {
            return b.lo.x >= a.hi.x || b.hi.x <= a.lo.x || b.lo.y >= a.hi.y || b.hi.y <= a.lo.y;
        };
        const double eps = touchingTolerance(both);
        for (const Flat& g : charts_[n].corners) {
            Bounds2 b;
            b.extend(g);
            if (apart(own, b)) continue;
            for (std::size_t k = 0; k < boxes.size(); ++k)
                if (!apart(boxes[k], b) && interiorsOverlap(way.corners[k], g, eps)) return std::nullopt;
        }
        return way;
    }

    const std::vector<Triangle>& triangles_;
    const std::vector<std::uint32_t>& groups_;
    const ChartOptions& options_;
    const TriangleFacts& facts_;
    std::vector<FlatChart> charts_;
    std::vector<std::uint32_t> chartOf_, slot_;  // per triangle: its chart, and its place in the chart's lists
    std::vector<double> area_;
    std::vector<Bounds2> box_;
};

// Phase 1: regions of edge-connected triangles within a 20-degree cone, merged up to the
// options' cone (merged), each laid flat and cut in two where it will not lie flat (flatten).
class ChartMaker {
public:
    ChartMaker(const std::vector<Triangle>& triangles, const std::vector<std::uint32_t>& groups,
               const ChartOptions& options)
        : triangles_(triangles), groups_(groups), options_(options), facts_(triangleFacts(triangles)),
          available_(triangles.size(), 0) {}

    ChartSet make() {
        std::vector<std::uint32_t> all(triangles_.size());
        for (std::uint32_t t = 0; t < all.size(); ++t) all[t] = t;
        ChartSet set;
        for (std::vector<std::uint32_t>& region : merged(regions(all, kFirstConeDegrees))) {
            std::sort(region.begin(), region.end());
            flatten(std::move(region), set.charts);
        }
        if (options_.attachArea > 0.0) set.charts = ChartAttacher(triangles_, groups_, options_, facts_).attached(std::move(set.charts));
        set.area = facts_.area;
        return set;
    }

private:
    // The region (ascending) laid flat by the conformal map where that is acceptable; else cut in
    // two (split) and each part laid flat the same way.
    void flatten(std::vector<std::uint32_t> first, std::vector<FlatChart>& out) {
        // Depth first, each region's parts in order (a stack, not recursion: a region may be cut
        // as many times as it has triangles).
        std::vector<std::vector<std::uint32_t>> pending;
        pending.push_back(std::move(first));
        while (!pending.empty()) {
            std::vector<std::uint32_t> region = std::move(pending.back());
            pending.pop_back();
            if (facts_.normal[region.front()] == glm::dvec3(0.0)) {  // a point of its own
                out.push_back(settled(std::move(region), {Flat{}}));
                continue;
            }
            std::vector<Triangle> world;
            for (std::uint32_t t : region) world.push_back(triangles_[t]);
            std::optional<std::vector<Flat>> flat = conformalMap(world);
            if (flat && acceptable(region, *flat, facts_, options_.stretchLimit)) {
                out.push_back(settled(std::move(region), std::move(*flat)));
                continue;
            }
            // Sliver triangles (common in CAD tessellations) can fold the conformal map where a
            // plain projection onto the plane of the mean normal stays flat and close enough.
            std::vector<Flat> projected = projectedOnMeanPlane(region);
            if (region.size() == 1 || acceptable(region, projected, facts_, options_.stretchLimit)) {
                out.push_back(settled(std::move(region), std::move(projected)));
                continue;
            }
            std::vector<std::vector<std::uint32_t>> parts = split(region);
            for (auto part = parts.rbegin(); part != parts.rend(); ++part) pending.push_back(std::move(*part));
        }
    }

    // The region projected onto the plane of its mean normal (by area), scaled to its surface's
    // area; flipped triangles where its normals turn past that plane.
    std::vector<Flat> projectedOnMeanPlane(const std::vector<std::uint32_t>& region) const {
        const NormalCone cone = coneOf(region);
        glm::dvec3 u, v;
        planeAxes(cone.axis, &u, &v);
        const glm::dvec3 origin = triangles_[region.front()][0];
        std::vector<Flat> flat;
        double surface = 0.0, area = 0.0;
        for (std::uint32_t t : region) {
            Triangle shifted = triangles_[t];
            for (glm::dvec3& p : shifted) p -= origin;
            flat.push_back(project(shifted, u, v, 1.0));
            surface += facts_.area[t];
            area += signedArea(flat.back());
        }
        if (area > 0.0)
            for (Flat& f : flat)
                for (glm::dvec2& p : f) p *= std::sqrt(surface / area);
        return flat;
    }

    // The region (ascending, two triangles or more) cut in two where it turns most: by the side
    // of the plane through its mean normal across the direction in which its normals spread
    // most; where they do not spread (a flat region that overlaps itself), across the direction
    // in which its triangles' centres spread most. Each side's connected parts, ascending.
    std::vector<std::vector<std::uint32_t>> split(const std::vector<std::uint32_t>& region) {
        auto spread = [&](auto value) {  // the mean and the direction of largest variance
            glm::dvec3 mean(0.0);
            double weight = 0.0;
            for (std::uint32_t t : region) mean += facts_.area[t] * value(t), weight += facts_.area[t];
            mean /= weight;
            Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
            for (std::uint32_t t : region) {
                const glm::dvec3 d = value(t) - mean;
                const Eigen::Vector3d v(d.x, d.y, d.z);
                covariance += facts_.area[t] * v * v.transpose();
            }
            const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(covariance / weight);
            const Eigen::Vector3d axis = eigen.eigenvectors().col(2);
            return std::make_tuple(mean, glm::dvec3(axis.x(), axis.y(), axis.z()), eigen.eigenvalues()(2));
        };
        auto centre = [&](std::uint32_t t) { return (triangles_[t][0] + triangles_[t][1] + triangles_[t][2]) / 3.0; };
        auto [mean, axis, variance] = spread([&](std::uint32_t t) { return facts_.normal[t]; });
        std::function<glm::dvec3(std::uint32_t)> value = [&](std::uint32_t t) { return facts_.normal[t]; };
        if (!(variance > 1e-12)) {
            std::tie(mean, axis, variance) = spread(centre);
            value = centre;
        }
        std::vector<std::uint8_t> side(region.size());
        std::size_t above = 0;
        for (std::size_t k = 0; k < region.size(); ++k) above += side[k] = glm::dot(value(region[k]) - mean, axis) >= 0.0;
        if (above == 0 || above == region.size())  // no plane parts them: halves in order
            for (std::size_t k = 0; k < region.size(); ++k) side[k] = k < region.size() / 2;
        // Connected parts of each side.
        std::map<std::uint32_t, std::size_t> at;
        for (std::size_t k = 0; k < region.size(); ++k) at.emplace(region[k], k);
        std::vector<bool> done(region.size(), false);
        std::vector<std::vector<std::uint32_t>> parts;
        for (std::size_t k = 0; k < region.size(); ++k) {
            if (done[k]) continue;
            done[k] = true;
            std::vector<std::uint32_t> part{region[k]};
            for (std::size_t next = 0; next < part.size(); ++next)
                for (std::uint32_t u : facts_.neighbours[part[next]]) {
                    const auto found = at.find(u);
                    if (found == at.end() || done[found->second] || side[found->second] != side[k]) continue;
                    done[found->second] = true;
                    part.push_back(u);
                }
            std::sort(part.begin(), part.end());
            parts.push_back(std::move(part));
        }
        return parts;
    }

    // A cone that holds a set of unit normals: its axis and half-angle (radians).
    struct NormalCone {
        glm::dvec3 axis{0.0};
        double angle = 0.0;
    };

    // The smallest cone that holds two cones (an upper bound for the normals both hold).
    static NormalCone join(const NormalCone& a, const NormalCone& b) {
        const double between = std::acos(std::clamp(glm::dot(a.axis, b.axis), -1.0, 1.0));
        if (between + b.angle <= a.angle) return a;
        if (between + a.angle <= b.angle) return b;
        NormalCone c;
        c.angle = 0.5 * (between + a.angle + b.angle);
        if (c.angle >= 0.5 * kPi) {  // no use past a half space: the merge is refused anyway
            c.axis = a.axis;
            return c;
        }
        // Turn a's axis towards b's by the angle that puts both cones' far edges on c's.
        const double turn = c.angle - a.angle;
        const double s = std::sin(between);
        c.axis = s > 1e-12 ? glm::normalize((std::sin(between - turn) * a.axis + std::sin(turn) * b.axis) / s) : a.axis;
        return c;
    }

    // A cone about the regions' mean normal (by area) that holds each of their normals.
    NormalCone coneOf(const std::vector<std::uint32_t>& region, const std::vector<std::uint32_t>& more = {}) const {
        glm::dvec3 sum(0.0);
        for (const auto* part : {&region, &more})
            for (std::uint32_t t : *part) sum += facts_.area[t] * facts_.normal[t];
        NormalCone cone{facts_.normal[region.front()], 0.0};
        if (glm::length(sum) > 0.0) cone.axis = glm::normalize(sum);
        for (const auto* part : {&region, &more})
            for (std::uint32_t t : *part)
                cone.angle =
                    std::max(cone.angle, std::acos(std::clamp(glm::dot(cone.axis, facts_.normal[t]), -1.0, 1.0)));
        return cone;
    }

    // Regions merged, the smallest by area first, each into the neighbour with which it shares
    // the longest length of edges that are no crease, where both are of one group and the cone
    // that holds both their normals stays within the options' cone. What a merge leaves is a
    // region again, merged on in its turn. Regions of degenerate triangles are left alone.
    std::vector<std::vector<std::uint32_t>> merged(std::vector<std::vector<std::uint32_t>> regions) const {
        const std::size_t count = regions.size();
        std::vector<std::uint32_t> regionOf(triangles_.size());
        std::vector<NormalCone> cone(count);
        std::vector<double> area(count, 0.0);
        double total = 0.0;
        // Per neighbour, the length of edges shared with it: those that are no crease, and all.
        struct Shared {
            double smooth = 0.0, all = 0.0;
        };
        std::vector<std::map<std::uint32_t, Shared>> shared(count);
        for (std::uint32_t r = 0; r < count; ++r) {
            for (std::uint32_t t : regions[r]) {
                regionOf[t] = r;
                area[r] += facts_.area[t];
            }
            total += area[r];
            cone[r] = coneOf(regions[r]);
        }
        const double cosCrease = std::cos(options_.creaseDegrees * kPi / 180.0);
        auto group = [&](std::uint32_t t) { return groups_.empty() ? 0u : groups_[t]; };
        for (std::uint32_t t = 0; t < triangles_.size(); ++t) {
            if (facts_.normal[t] == glm::dvec3(0.0)) continue;
            for (int e = 0; e < 3; ++e) {
                const glm::dvec3 &p = triangles_[t][e], &q = triangles_[t][(e + 1) % 3];
                for (std::uint32_t u : facts_.neighbours[t]) {
                    if (regionOf[u] == regionOf[t] || group(u) != group(t)) continue;
                    bool hasP = false, hasQ = false;
                    for (const glm::dvec3& c : triangles_[u]) hasP = hasP || c == p, hasQ = hasQ || c == q;
                    if (!(hasP && hasQ)) continue;
                    Shared& s = shared[regionOf[t]][regionOf[u]];
                    s.all += glm::length(q - p);
                    if (glm::dot(facts_.normal[t], facts_.normal[u]) >= cosCrease) s.smooth += glm::length(q - p);
                }
            }
        }
        const double largest = options_.coneDegrees * kPi / 180.0;
        const double small = total * kSmallShare;
        using Entry = std::pair<double, std::uint32_t>;
        std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> smallest;
        for (std::uint32_t r = 0; r < count; ++r)
            if (facts_.normal[regions[r].front()] != glm::dvec3(0.0)) smallest.emplace(area[r], r);
        std::vector<bool> alive(count, true);
        while (!smallest.empty()) {
            const auto [a, r] = smallest.top();
            smallest.pop();
            if (!alive[r] || a != area[r]) continue;  // merged away, or an old entry
            // A small region may cross a crease: its light is a few texels' either way.
            const bool crosses = area[r] < small;
            std::uint32_t into = 0;
            double longest = 0.0;
            NormalCone joined;
            for (const auto& [n, s] : shared[r]) {
                const double length = crosses ? s.all : s.smooth;
                if (length <= longest) continue;
                // The cone of two cones is quick but may be wider than the normals need.
                NormalCone c = join(cone[n], cone[r]);
                if (c.angle > largest) c = coneOf(regions[n], regions[r]);
                if (c.angle > largest) continue;
                into = n, longest = length, joined = c;
            }
            if (!(longest > 0.0)) continue;  // final
            for (const auto& [n, s] : shared[r]) {
                const Shared back = shared[n][r];
                shared[n].erase(r);
                if (n == into) continue;
                shared[n][into].smooth += back.smooth, shared[n][into].all += back.all;
                shared[into][n].smooth += s.smooth, shared[into][n].all += s.all;
            }
            shared[into].erase(r);
            shared[r].clear();
            regions[into].insert(regions[into].end(), regions[r].begin(), regions[r].end());
            regions[r].clear();
            alive[r] = false;
            cone[into] = joined;
            area[into] += area[r];
            smallest.emplace(area[into], into);
        }
        std::vector<std::vector<std::uint32_t>> out;
        for (std::uint32_t r = 0; r < count; ++r)
            if (alive[r]) out.push_back(std::move(regions[r]));
        return out;
    }

    // Connected regions of `subset` (ascending): each grown breadth-first from the first triangle
    // not yet in one, across edges to triangles of its group whose normals lie within the crease
    // angle of the one they are reached from and within the cone of the first one's. A triangle
    // without a normal is a region of its own.
    std::vector<std::vector<std::uint32_t>> regions(const std::vector<std::uint32_t>& subset, double coneDegrees) {
        const double cosCone = std::cos(coneDegrees * kPi / 180.0);
        const double cosCrease = std::cos(options_.creaseDegrees * kPi / 180.0);
        const std::vector<glm::dvec3>& normal = facts_.normal;
        auto group = [&](std::uint32_t t) { return groups_.empty() ? 0u : groups_[t]; };
        for (std::uint32_t t : subset) available_[t] = 1;
        std::vector<std::vector<std::uint32_t>> out;
        for (std::uint32_t seed : subset) {
            if (!available_[seed]) continue;
            available_[seed] = 0;
            std::vector<std::uint32_t> region{seed};
            const glm::dvec3 axis = normal[seed];
            for (std::size_t next = 0; next < region.size() && axis != glm::dvec3(0.0); ++next) {
                const std::uint32_t from = region[next];
                for (std::uint32_t t : facts_.neighbours[from]) {
                    if (!available_[t] || normal[t] == glm::dvec3(0.0) || group(t) != group(seed)) continue;
                    if (glm::dot(normal[t], normal[from]) < cosCrease || glm::dot(normal[t], axis) < cosCone) continue;
                    available_[t] = 0;
                    region.push_back(t);
                }
            }
            out.push_back(std::move(region));
        }
        for (std::uint32_t t : subset) available_[t] = 0;
        return out;
    }

    static constexpr double kFirstConeDegrees = 20.0;  // the regions merging starts from
    // A region under this share of the surface may cross a crease when it merges.
    static constexpr double kSmallShare = 1.0 / 4096.0;

    const std::vector<Triangle>& triangles_;
    const std::vector<std::uint32_t>& groups_;
    ChartOptions options_;
    TriangleFacts facts_;
    std::vector<std::uint8_t> available_;  // scratch: in the subset being grown, not yet taken
};

// Phase 2: the charts packed by their texels (chart_packing.h), each triangle's texel
// coordinates turned with its chart where the chart was turned.
void packCharts(Atlas& atlas) {
    std::vector<ChartTexels> texels(atlas.charts.size());
    for (std::size_t c = 0; c < atlas.charts.size(); ++c) {
        texels[c].width = atlas.charts[c].width;
        texels[c].height = atlas.charts[c].height;
        for (std::uint32_t t : atlas.charts[c].triangles) texels[c].corners.push_back(atlas.texels[t]);
    }
    const std::vector<ChartPlacement> placement = packChartTexels(texels, atlas.pageSize, atlas.gutter, &atlas.pages, &atlas.pagesFilled);
    for (std::size_t c = 0; c < atlas.charts.size(); ++c) {
        AtlasChart& chart = atlas.charts[c];
        chart.page = placement[c].page;
        chart.x = placement[c].x;
        chart.y = placement[c].y;
        for (int turn = 0; turn < placement[c].quarterTurns; ++turn) {
            for (std::uint32_t t : chart.triangles)
                for (glm::dvec2& p : atlas.texels[t]) p = glm::dvec2(chart.height - p.y, p.x);
            std::swap(chart.width, chart.height);
        }
    }
}

// Phase 3: each triangle's texel coordinates moved to where its chart was packed, and what the
// atlas makes of the pages' texels and the surface.
void placeTexels(const std::vector<double>& area, Atlas& atlas) {
    double used = 0.0, stretched = 0.0, surface = 0.0;
    for (std::size_t t = 0; t < atlas.texels.size(); ++t) {
        AtlasChart& chart = atlas.charts[atlas.chartOf[t]];
        for (glm::dvec2& p : atlas.texels[t]) p += glm::dvec2(chart.x, chart.y);
        const double flat = flatArea(atlas.texels[t]);
        used += flat;
        if (!(flat > 0.0 && area[t] > 0.0)) continue;
        const double ratio = area[t] / (flat * atlas.texelSize * atlas.texelSize);
        const double stretch = std::max(ratio, 1.0 / ratio);
        chart.stretch = std::max(chart.stretch, stretch);
        atlas.largestStretch = std::max(atlas.largestStretch, stretch);
        stretched += stretch * area[t];
        surface += area[t];
    }
    if (surface > 0.0) atlas.meanStretch = stretched / surface;
    const double side = atlas.pageSize;
    if (atlas.pages > 0) atlas.areaUse = used / (static_cast<double>(atlas.pages) * side * side);
}

}  // namespace

ChartSet makeCharts(const std::vector<Triangle>& triangles, const std::vector<std::uint32_t>& groups,
                    const ChartOptions& options) {
    checkChartOptions(options);
    if (!groups.empty() && groups.size() != triangles.size())
        throw InputError("a lightmap atlas needs one group per triangle");
    return ChartMaker(triangles, groups, options).make();
}

// Each chart at the texel size as it is where it fits a page; cut by projection within the page
// where it does not.
AtlasAttempt tryAtlas(const std::vector<Triangle>& triangles, const ChartSet& charts, const AtlasOptions& options) {
    checkAtlasOptions(options);
    Atlas atlas;
    atlas.texelSize = options.texelSize;
    atlas.pageSize = options.pageSize;
    atlas.gutter = options.gutter;
    atlas.chartOf.assign(triangles.size(), 0);
    atlas.texels.resize(triangles.size());
    AtlasAttempt attempt;
    const double room = options.pageSize - 2.0 * options.gutter;  // texels a chart may span
    TriangleFacts facts;  // for cutting by projection, made when first needed
    std::vector<std::uint8_t> available;
    auto add = [&](const std::vector<std::uint32_t>& members, const std::vector<Flat>& flats, glm::dvec2 lo,
                   glm::dvec2 span) {
        const auto c = static_cast<std::uint32_t>(atlas.charts.size());
        AtlasChart chart;
        for (std::size_t k = 0; k < members.size(); ++k) {
            atlas.chartOf[members[k]] = c;
            for (int corner = 0; corner < 3; ++corner) atlas.texels[members[k]][corner] = flats[k][corner] - lo;
        }
        chart.triangles = members;
        std::sort(chart.triangles.begin(), chart.triangles.end());
        // Texels the chart spans, a span within rounding of a whole number taken as that number.
        auto texels = [](double x) { return std::max(1.0, std::ceil(x - 1e-9 * std::max(1.0, x))); };
        chart.width = static_cast<std::uint32_t>(texels(span.x));
        chart.height = static_cast<std::uint32_t>(texels(span.y));
        atlas.charts.push_back(std::move(chart));
    };
    for (const FlatChart& flat : charts.charts) {
        const glm::dvec2 span = flat.extent / options.texelSize;
        if (span.x <= room && span.y <= room) {
            std::vector<Flat> texels = flat.corners;
            for (Flat& f : texels)
                for (glm::dvec2& p : f) p /= options.texelSize;
            add(flat.triangles, texels, glm::dvec2(0.0), span);
            continue;
        }
        if (facts.area.empty()) {
            facts = triangleFacts(triangles);
            available.assign(triangles.size(), 0);
        }
        std::vector<ProjectedChart> projected;
        if (const std::optional<OversizedTriangle> oversized =
                projectCharts(triangles, facts, flat.triangles, options.texelSize, room, available, &projected)) {
            attempt.oversized = *oversized;
            return attempt;
        }
        for (const ProjectedChart& p : projected) add(p.members, p.flats, p.box.lo, p.box.hi - p.box.lo);
    }
    packCharts(atlas);
    placeTexels(charts.area, atlas);
    attempt.atlas = std::move(atlas);
    return attempt;
}

Atlas buildAtlas(const std::vector<Triangle>& triangles, const AtlasOptions& options) {
    checkAtlasOptions(options);
    AtlasAttempt attempt = tryAtlas(triangles, makeCharts(triangles, {}, options.charts), options);
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
