#include "scene/polygon_split.h"

#include <cmath>
#include <numeric>

#include "scene/mesh_readers.h"

namespace rad {

namespace {

struct Point {
    double x, y;
};

// Twice the signed area of (a, b, c): positive when they turn counter-clockwise.
double turn(const Point& a, const Point& b, const Point& c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// Whether p lies in the counter-clockwise triangle (a, b, c) or on its boundary.
bool inside(const Point& p, const Point& a, const Point& b, const Point& c) {
    return turn(a, b, p) >= 0.0 && turn(b, c, p) >= 0.0 && turn(c, a, p) >= 0.0;
}

bool samePoint(const Point& a, const Point& b) { return a.x == b.x && a.y == b.y; }

std::vector<std::array<std::size_t, 3>> fan(std::size_t n) {
    std::vector<std::array<std::size_t, 3>> triangles;
    for (std::size_t c = 1; c + 1 < n; ++c) triangles.push_back({0, c, c + 1});
    return triangles;
}

}  // namespace

std::vector<std::array<std::size_t, 3>> splitPolygon(const std::vector<glm::dvec3>& corners) {
    const std::size_t n = corners.size();
    if (n <= 3) return fan(n);

    // Newell's normal: the polygon turns counter-clockwise about it, planar or not.
    glm::dvec3 normal(0.0);
    for (std::size_t i = 0; i < n; ++i) {
        const glm::dvec3& a = corners[i];
        const glm::dvec3& b = corners[(i + 1) % n];
        normal += glm::dvec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
    }
    const glm::dvec3 size = glm::abs(normal);
    const int drop = size.x > size.y ? (size.x > size.z ? 0 : 2) : (size.y > size.z ? 1 : 2);
    if (!(size[drop] > 0.0)) return fan(n);  // no area: nothing to keep inside
    // The plane's two other axes, in the order that keeps the polygon counter-clockwise.
    int u = (drop + 1) % 3, v = (drop + 2) % 3;
    if (normal[drop] < 0.0) std::swap(u, v);
    std::vector<Point> p(n);
    for (std::size_t i = 0; i < n; ++i) p[i] = {corners[i][u], corners[i][v]};

    bool convex = true;
    for (std::size_t i = 0; i < n && convex; ++i) convex = turn(p[(i + n - 1) % n], p[i], p[(i + 1) % n]) >= 0.0;
    if (convex) return fan(n);

    // Ear clipping: a corner is an ear when it turns counter-clockwise and no other remaining
    // corner lies in the triangle it makes with its neighbours; cutting it off leaves a smaller
    // simple polygon. About n^2 steps for n corners.
    std::vector<std::array<std::size_t, 3>> triangles;
    std::vector<std::size_t> left(n);
    std::iota(left.begin(), left.end(), std::size_t{0});
    std::size_t i = 0, misses = 0, fruitless = 0;
    while (left.size() > 3) {
        const std::size_t m = left.size();
        // A simple polygon always has an ear (Meisters' two ears theorem); one that crosses itself
        // may find none for whole rounds of m tests of m corners each. Past about 2^26 steps of
        // such rounds (a fraction of a second) what is left is split as a fan: it has no inside.
        if (misses >= m) fruitless += m * m;
        if (fruitless > (std::size_t{1} << 26)) {
            for (std::size_t k = 1; k + 1 < m; ++k) triangles.push_back({left[0], left[k], left[k + 1]});
            return triangles;
        }
        i %= m;
        const std::size_t a = left[(i + m - 1) % m], b = left[i], c = left[(i + 1) % m];
        bool ear = turn(p[a], p[b], p[c]) > 0.0;
        for (std::size_t k = 0; ear && k < m; ++k) {
            const std::size_t q = left[k];
            if (q == a || q == b || q == c || samePoint(p[q], p[a]) || samePoint(p[q], p[b]) || samePoint(p[q], p[c]))
                continue;
            if (inside(p[q], p[a], p[b], p[c])) ear = false;
        }
        if (ear || misses >= m) {  // a whole round without an ear: the polygon is not simple
            triangles.push_back({a, b, c});
            left.erase(left.begin() + static_cast<std::ptrdiff_t>(i));
            i = i == 0 ? 0 : i - 1;  // the corner before, which may have become an ear
            misses = 0;
        } else {
            ++i;
            ++misses;
        }
    }
    triangles.push_back({left[0], left[1], left[2]});
    return triangles;
}

void appendPolygon(const std::vector<std::uint32_t>& polygon, int material, FileSurface& surface) {
    std::vector<glm::dvec3> corners;
    corners.reserve(polygon.size());
    for (std::uint32_t v : polygon) corners.push_back(surface.positions[v]);
    for (const auto& t : splitPolygon(corners)) {
        surface.triangles.push_back({polygon[t[0]], polygon[t[1]], polygon[t[2]]});
        surface.materials.push_back(material);
    }
}

}  // namespace rad
