// The lightmap atlas (host/lightmap/chart_atlas.h): charts that do not overlap and keep their
// gutters, one texel size everywhere up to the stated stretch, and clear refusals.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <set>
#include <vector>

#include <glm/geometric.hpp>

#include "lightmap/chart_atlas.h"
#include "lightmap/conformal_map.h"
#include "util/error.h"

namespace rad {
namespace {

using Triangle = std::array<glm::dvec3, 3>;

// A w x h grid of quads (two triangles each) spanning origin + [0,1] a + [0,1] b.
void addGrid(std::vector<Triangle>& out, glm::dvec3 origin, glm::dvec3 a, glm::dvec3 b, int w, int h) {
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            const glm::dvec3 p = origin + a * (double(i) / w) + b * (double(j) / h);
            const glm::dvec3 q = p + a / double(w), r = p + b / double(h), s = q + b / double(h);
            out.push_back({p, q, s});
            out.push_back({p, s, r});
        }
}

// The closed unit box, each face a grid of n x n quads, wound outwards.
std::vector<Triangle> box(int n) {
    std::vector<Triangle> t;
    const glm::dvec3 o(0.0), x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
    addGrid(t, o, y, x, n, n);      // bottom, normal -z
    addGrid(t, o + z, x, y, n, n);  // top, +z
    addGrid(t, o, x, z, n, n);      // front, -y
    addGrid(t, o + y, z, x, n, n);  // back, +y
    addGrid(t, o, z, y, n, n);      // left, -x
    addGrid(t, o + x, y, z, n, n);  // right, +x
    return t;
}

double flatArea(const std::array<glm::dvec2, 3>& f) {
    return 0.5 * std::fabs((f[1].x - f[0].x) * (f[2].y - f[0].y) - (f[2].x - f[0].x) * (f[1].y - f[0].y));
}

// Whether point p lies strictly inside flat triangle f (by more than eps from every edge).
bool strictlyInside(const std::array<glm::dvec2, 3>& f, glm::dvec2 p, double eps) {
    const double area2 = (f[1].x - f[0].x) * (f[2].y - f[0].y) - (f[2].x - f[0].x) * (f[1].y - f[0].y);
    if (area2 == 0.0) return false;
    for (int e = 0; e < 3; ++e) {
        const glm::dvec2 a = f[e], b = f[(e + 1) % 3];
        const double side = ((b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x)) / std::copysign(1.0, area2);
        if (side <= eps * std::hypot(b.x - a.x, b.y - a.y)) return false;
    }
    return true;
}

// Every check an atlas must pass, whatever the input: each triangle inside its chart's
// rectangle, rectangles inside their pages and two gutters apart, no texel sample covered by two
// triangles, and each triangle's texel area its surface area over texelSize^2, shrunk by at most
// the reported stretch (and that stretch within the cone's bound).
void expectValidAtlas(const std::vector<Triangle>& triangles, const Atlas& atlas, const AtlasOptions& options) {
    ASSERT_EQ(atlas.chartOf.size(), triangles.size());
    const double slack = 1e-9 * atlas.pageSize;
    for (std::size_t t = 0; t < triangles.size(); ++t) {
        const AtlasChart& c = atlas.charts[atlas.chartOf[t]];
        EXPECT_TRUE(std::binary_search(c.triangles.begin(), c.triangles.end(), std::uint32_t(t))) << "triangle " << t;
        for (const glm::dvec2& p : atlas.texels[t]) {
            EXPECT_GE(p.x, c.x - slack) << "triangle " << t;
            EXPECT_LE(p.x, c.x + c.width + slack) << "triangle " << t;
            EXPECT_GE(p.y, c.y - slack) << "triangle " << t;
            EXPECT_LE(p.y, c.y + c.height + slack) << "triangle " << t;
        }
        const glm::dvec3 n = glm::cross(triangles[t][1] - triangles[t][0], triangles[t][2] - triangles[t][0]);
        const double surface = 0.5 * glm::length(n) / (options.texelSize * options.texelSize);
        const double texels = flatArea(atlas.texels[t]);
        EXPECT_LE(texels, surface * atlas.largestStretch * (1.0 + 1e-9)) << "triangle " << t;
        EXPECT_GE(texels * atlas.largestStretch, surface * (1.0 - 1e-9)) << "triangle " << t;
    }
    EXPECT_LE(atlas.largestStretch, options.charts.stretchLimit * (1.0 + 1e-9));
    EXPECT_GE(atlas.meanStretch, 1.0);
    EXPECT_LE(atlas.meanStretch, atlas.largestStretch);
    for (std::size_t i = 0; i < atlas.charts.size(); ++i) EXPECT_LT(atlas.charts[i].page, atlas.pages);
    // Coverage at 4 x 4 samples per texel over every page: no sample inside two triangles; and
    // the texels a chart's samples fall in lie at least 2 gutters from any other chart's and 1
    // gutter from the page's edge.
    const long g = atlas.gutter, side = atlas.pageSize;
    for (std::uint32_t page = 0; page < atlas.pages; ++page) {
        std::vector<std::uint8_t> covered(std::size_t(side) * side * 16, 0);
        std::vector<long> owner(std::size_t(side) * side, -1);
        for (std::size_t t = 0; t < triangles.size(); ++t) {
            if (atlas.charts[atlas.chartOf[t]].page != page) continue;
            const auto& f = atlas.texels[t];
            const int x0 = std::max(0, int(std::floor(std::min({f[0].x, f[1].x, f[2].x}) * 4)));
            const int x1 = std::min(int(side) * 4 - 1, int(std::ceil(std::max({f[0].x, f[1].x, f[2].x}) * 4)));
            const int y0 = std::max(0, int(std::floor(std::min({f[0].y, f[1].y, f[2].y}) * 4)));
            const int y1 = std::min(int(side) * 4 - 1, int(std::ceil(std::max({f[0].y, f[1].y, f[2].y}) * 4)));
            for (int y = y0; y <= y1; ++y)
                for (int x = x0; x <= x1; ++x)
                    if (strictlyInside(f, glm::dvec2((x + 0.5) / 4.0, (y + 0.5) / 4.0), 1e-9)) {
                        std::uint8_t& c = covered[std::size_t(y) * side * 4 + x];
                        EXPECT_EQ(c, 0) << "page " << page << " sample (" << x << ", " << y << ") covered twice";
                        if (c != 0) return;
                        c = 1;
                        owner[std::size_t(y / 4) * side + x / 4] = long(atlas.chartOf[t]);
                    }
        }
        for (long y = 0; y < side; ++y)
            for (long x = 0; x < side; ++x) {
                const long mine = owner[std::size_t(y) * side + x];
                if (mine < 0) continue;
                EXPECT_TRUE(x >= g && y >= g && x + g < side && y + g < side)
                    << "chart " << mine << " at texel (" << x << ", " << y << ") within a gutter of the page's edge";
                for (long v = std::max(0L, y - 2 * g); v <= std::min(side - 1, y + 2 * g); ++v)
                    for (long u = std::max(0L, x - 2 * g); u <= std::min(side - 1, x + 2 * g); ++u) {
                        const long other = owner[std::size_t(v) * side + u];
                        if (other >= 0 && other != mine) {
                            ADD_FAILURE() << "charts " << mine << " and " << other << " hold texels (" << x << ", " << y
                                          << ") and (" << u << ", " << v << "), closer than two gutters";
                            return;
                        }
                    }
            }
    }
}

TEST(LightmapAtlas, ABoxGetsOneChartPerFaceAtTheTexelSizeExactly) {
    const std::vector<Triangle> triangles = box(4);  // 192 triangles
    AtlasOptions options;
    options.texelSize = 1.0 / 60.0;
    options.pageSize = 256;
    options.gutter = 2;
    const Atlas atlas = buildAtlas(triangles, options);
    // Faces meet at 90 degrees, creases: six flat charts of 60 x 60 texels.
    ASSERT_EQ(atlas.charts.size(), 6u);
    for (const AtlasChart& c : atlas.charts) {
        EXPECT_EQ(c.triangles.size(), 32u);
        EXPECT_EQ(c.width, 60u);
        EXPECT_EQ(c.height, 60u);
    }
    EXPECT_EQ(atlas.pages, 1u);
    EXPECT_NEAR(atlas.largestStretch, 1.0, 1e-9);  // flat charts keep their shape
    EXPECT_NEAR(atlas.areaUse, 6.0 * 3600.0 / (256.0 * 256.0), 1e-9);
    expectValidAtlas(triangles, atlas, options);
}

// An open tube of radius 1 and height 1 (its axis along z) in `facets` facets around by `rows`
// rows, wound outwards; `turn` of a full turn of it.
std::vector<Triangle> tube(int facets, int rows, double turn = 1.0) {
    std::vector<Triangle> triangles;
    const double pi = 3.14159265358979323846;
    for (int i = 0; i < facets; ++i)
        for (int j = 0; j < rows; ++j) {
            const double a0 = 2.0 * pi * turn * i / facets, a1 = 2.0 * pi * turn * (i + 1) / facets;
            const double z0 = double(j) / rows, z1 = double(j + 1) / rows;
            const glm::dvec3 p(std::cos(a0), std::sin(a0), z0), q(std::cos(a1), std::sin(a1), z0);
            const glm::dvec3 up(0, 0, z1 - z0);
            triangles.push_back({p, q, p + up});
            triangles.push_back({q, q + up, p + up});
        }
    return triangles;
}

TEST(ConformalMap, UnrollsACylinderWithoutChangingALength) {
    // A third of a tube: developable, so the conformal map is an isometry (a plane's rotation
    // and shift): every edge keeps its length.
    const std::vector<Triangle> triangles = tube(40, 5, 1.0 / 3.0);
    const auto flat = conformalMap(triangles);
    ASSERT_TRUE(flat.has_value());
    for (std::size_t t = 0; t < triangles.size(); ++t)
        for (int e = 0; e < 3; ++e) {
            const double world = glm::length(triangles[t][(e + 1) % 3] - triangles[t][e]);
            const double plane = glm::length((*flat)[t][(e + 1) % 3] - (*flat)[t][e]);
            ASSERT_NEAR(plane, world, 1e-9 * world) << "triangle " << t << " edge " << e;
        }
}

TEST(ConformalMap, KeepsAnglesOnACurvedPatch) {
    // A piece of a sphere is not developable: its triangles change size in the plane, but a
    // conformal map keeps their shape (angles) up to the facets' own discretisation.
    std::vector<Triangle> triangles;
    const int n = 24;
    auto at = [](double u, double v) { return glm::normalize(glm::dvec3(u, v, 1.0)); };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const double u0 = -0.8 + 1.6 * i / n, u1 = -0.8 + 1.6 * (i + 1) / n;
            const double v0 = -0.8 + 1.6 * j / n, v1 = -0.8 + 1.6 * (j + 1) / n;
            triangles.push_back({at(u0, v0), at(u1, v0), at(u1, v1)});
            triangles.push_back({at(u0, v0), at(u1, v1), at(u0, v1)});
        }
    const auto flat = conformalMap(triangles);
    ASSERT_TRUE(flat.has_value());
    auto angle = [](glm::dvec3 a, glm::dvec3 b) { return std::acos(glm::dot(glm::normalize(a), glm::normalize(b))); };
    auto angle2 = [](glm::dvec2 a, glm::dvec2 b) { return std::acos(glm::dot(glm::normalize(a), glm::normalize(b))); };
    double worst = 0.0, smallest = 1e300, largest = 0.0;
    for (std::size_t t = 0; t < triangles.size(); ++t) {
        const auto& w = triangles[t];
        const auto& f = (*flat)[t];
        worst = std::max(worst, std::fabs(angle(w[1] - w[0], w[2] - w[0]) - angle2(f[1] - f[0], f[2] - f[0])));
        const double ratio = flatArea(f) / (0.5 * glm::length(glm::cross(w[1] - w[0], w[2] - w[0])));
        smallest = std::min(smallest, ratio), largest = std::max(largest, ratio);
    }
    EXPECT_LT(worst, 0.02);              // radians; the facets turn by 0.06 from one to the next
    EXPECT_GT(largest / smallest, 1.2);  // and yet sizes change: it is not an isometry
}

TEST(LightmapAtlas, ACylinderTakesAFewChartsWhateverItsTessellation) {
    // A closed tube cannot lie flat in one piece, and a chart's normals lie within a cone under
    // 90 degrees, so it takes at least three; but no more at four times the triangles, and each
    // chart is unrolled without stretch.
    for (const auto& [facets, rows] : {std::pair<int, int>{32, 2}, std::pair<int, int>{128, 8}}) {
        const std::vector<Triangle> triangles = tube(facets, rows);
        AtlasOptions options;
        options.texelSize = 0.01;
        options.pageSize = 1024;
        const Atlas atlas = buildAtlas(triangles, options);
        EXPECT_GE(atlas.charts.size(), 3u) << facets << " facets";
        EXPECT_LE(atlas.charts.size(), 4u) << facets << " facets";
        EXPECT_LT(atlas.largestStretch, 1.0 + 1e-6) << facets << " facets";
        expectValidAtlas(triangles, atlas, options);
    }
}

TEST(LightmapAtlas, ACurvedCapStaysWithinTheStretchItStates) {
    // A spherical cap of 60 degrees about its pole, whose normals fit one chart's cone but whose
    // surface does not lie flat: one chart, its triangles' texel areas within the stated stretch
    // of their surface (expectValidAtlas), which is more than 1 and within the limit.
    std::vector<Triangle> triangles;
    const int rings = 12, sectors = 48;
    const double pi = 3.14159265358979323846;
    auto at = [&](int ring, int sector) {
        const double polar = (pi / 3.0) * ring / rings, azimuth = 2.0 * pi * sector / sectors;
        return glm::dvec3(std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth), std::cos(polar));
    };
    for (int r = 0; r < rings; ++r)
        for (int s = 0; s < sectors; ++s) {
            if (r > 0) triangles.push_back({at(r, s), at(r + 1, s), at(r, s + 1)});
            triangles.push_back({at(r, s + 1), at(r + 1, s), at(r + 1, s + 1)});
        }
    AtlasOptions options;
    options.texelSize = 0.005;
    options.pageSize = 512;
    const Atlas atlas = buildAtlas(triangles, options);
    EXPECT_EQ(atlas.charts.size(), 1u);
    EXPECT_GT(atlas.largestStretch, 1.05);
    expectValidAtlas(triangles, atlas, options);
}

TEST(LightmapAtlas, ARampThatWindsOverItselfIsCutBeforeItsChartOverlaps) {
    // A helical ramp: two full turns of 64 segments each, 0.3 wide, rising 0.05 a turn, so its
    // normals stay within a few degrees of up while its projection covers itself twice.
    std::vector<Triangle> triangles;
    const int segments = 128;
    for (int i = 0; i < segments; ++i) {
        const double a0 = 2.0 * 3.14159265358979 * i / 64, a1 = 2.0 * 3.14159265358979 * (i + 1) / 64;
        const double z0 = 0.05 * i / 64, z1 = 0.05 * (i + 1) / 64;
        const glm::dvec3 p0(std::cos(a0), std::sin(a0), z0), p1(std::cos(a1), std::sin(a1), z1);
        const glm::dvec3 q0 = 1.3 * glm::dvec3(p0.x, p0.y, 0.0) + glm::dvec3(0, 0, z0);
        const glm::dvec3 q1 = 1.3 * glm::dvec3(p1.x, p1.y, 0.0) + glm::dvec3(0, 0, z1);
        triangles.push_back({p0, q0, q1});
        triangles.push_back({p0, q1, p1});
    }
    AtlasOptions options;
    options.texelSize = 0.02;
    options.pageSize = 256;
    const Atlas atlas = buildAtlas(triangles, options);
    EXPECT_GE(atlas.charts.size(), 2u);  // one chart cannot hold both turns
    expectValidAtlas(triangles, atlas, options);
}

TEST(LightmapAtlas, ChartsPackByTheirTexelsNotTheirBoxes) {
    // Twenty-four L-shaped plates (a 3 x 3 square less a 2 x 2 corner: 5/9 of its box), apart
    // from each other. At 8 texels a unit each box is 24 x 24 texels, 26 x 26 with its gutters,
    // so no packing of boxes holds more than 16 on a page of 128 (4 x 4 of 26 <= 128 < 5 x 26);
    // packed by the texels they touch, the Ls nest and all 24 fit on one.
    std::vector<Triangle> triangles;
    const glm::dvec3 x(1, 0, 0), y(0, 1, 0);
    for (int k = 0; k < 24; ++k) {
        const glm::dvec3 o(10.0 * k, 0.0, 0.0);
        addGrid(triangles, o, 3.0 * x, y, 3, 1);          // the L's foot, 3 x 1
        addGrid(triangles, o + y, x, 2.0 * y, 1, 2);      // its upright, 1 x 2
    }
    AtlasOptions options;
    options.texelSize = 1.0 / 8.0;
    options.pageSize = 128;
    options.gutter = 1;
    const Atlas atlas = buildAtlas(triangles, options);
    EXPECT_EQ(atlas.charts.size(), 24u);
    EXPECT_EQ(atlas.pages, 1u);
    EXPECT_NEAR(atlas.areaUse, 24.0 * 5.0 * 64.0 / (128.0 * 128.0), 1e-6);
    expectValidAtlas(triangles, atlas, options);
}

// A hexagonal prism of circumradius 1 (a nut without its hole), wound outwards: six top
// triangles, six bottom, then two per side. Neighbouring faces meet at 60 or 90 degrees, so
// every face is a chart of its own until charts are attached.
std::vector<Triangle> hexagonalPrism(double height) {
    const double pi = 3.14159265358979323846;
    std::vector<Triangle> t;
    auto corner = [&](int i, double z) { return glm::dvec3(std::cos(pi / 3.0 * i), std::sin(pi / 3.0 * i), z); };
    for (int i = 0; i < 6; ++i) t.push_back({glm::dvec3(0, 0, height), corner(i, height), corner(i + 1, height)});
    for (int i = 0; i < 6; ++i) t.push_back({glm::dvec3(0, 0, 0), corner(i + 1, 0), corner(i, 0)});
    for (int i = 0; i < 6; ++i) {
        t.push_back({corner(i, 0), corner(i + 1, 0), corner(i + 1, height)});
        t.push_back({corner(i, 0), corner(i + 1, height), corner(i, height)});
    }
    return t;
}

// The pieces of each chart in the lightmap: its triangles joined where they share an edge of the
// mesh at the same texel coordinates (where a chart was unfolded onto another about a hinge).
std::vector<std::size_t> piecesPerChart(const std::vector<Triangle>& triangles, const Atlas& atlas) {
    std::vector<std::size_t> parent(triangles.size());
    for (std::size_t t = 0; t < parent.size(); ++t) parent[t] = t;
    std::function<std::size_t(std::size_t)> root = [&](std::size_t t) {
        return parent[t] == t ? t : parent[t] = root(parent[t]);
    };
    for (std::size_t a = 0; a < triangles.size(); ++a)
        for (std::size_t b = a + 1; b < triangles.size(); ++b) {
            if (atlas.chartOf[a] != atlas.chartOf[b]) continue;
            int met = 0;  // corners at the same place in space and in the lightmap
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j)
                    met += triangles[a][i] == triangles[b][j] && glm::length(atlas.texels[a][i] - atlas.texels[b][j]) < 1e-9;
            if (met >= 2) parent[root(a)] = root(b);
        }
    std::vector<std::set<std::size_t>> roots(atlas.charts.size());
    for (std::size_t t = 0; t < triangles.size(); ++t) roots[atlas.chartOf[t]].insert(root(t));
    std::vector<std::size_t> pieces;
    for (const auto& r : roots) pieces.push_back(r.size());
    return pieces;
}

TEST(LightmapAtlas, SmallFacesUnfoldAcrossCreasesOntoTheirNeighbours) {
    // A tray: a 1 x 1 m floor (4 x 4 quads) and a 0.1 m rim standing on each of its edges, all
    // wound outwards (the floor facing down); each rim face meets the floor at 90 degrees and its two
    // neighbours at 90, so without attaching every face is a chart of its own (5). Attached, the
    // rim faces (0.1 m^2 each, under the attach area; the floor, 1 m^2, is not) unfold onto the
    // floor or onto each other, whichever grows a box least: the first (the front) onto the
    // floor, with which it shares 1 m of edge (0.1 m with each other rim face); in all at most
    // three charts, each one piece, none stretched.
    std::vector<Triangle> triangles;
    const glm::dvec3 x(1, 0, 0), y(0, 1, 0), z(0, 0, 0.1);
    addGrid(triangles, glm::dvec3(0.0), y, x, 4, 4);       // the floor, -z (outwards, as the rim)
    addGrid(triangles, glm::dvec3(0.0), x, z, 4, 1);       // front rim, -y
    addGrid(triangles, y, z, x, 1, 4);                     // back rim, +y
    addGrid(triangles, glm::dvec3(0.0), z, y, 1, 4);       // left rim, -x
    addGrid(triangles, x, y, z, 4, 1);                     // right rim, +x
    EXPECT_EQ(makeCharts(triangles, {}, ChartOptions{}).charts.size(), 5u);  // nothing attached
    AtlasOptions options;
    options.texelSize = 1.0 / 64.0;
    options.pageSize = 256;
    options.charts.attachArea = 0.5;
    options.charts.attachExtent = 2.0;
    const Atlas atlas = buildAtlas(triangles, options);
    EXPECT_LE(atlas.charts.size(), 3u);
    for (std::size_t t = 32; t < 40; ++t) EXPECT_EQ(atlas.chartOf[t], atlas.chartOf[0]) << "front rim triangle " << t;
    // Flat faces are unfolded about edges of one length in both: no stretch at all.
    EXPECT_LE(atlas.largestStretch, 1.0 + 1e-9);
    // One piece each: every attached face meets its neighbour along its hinge at the same texels.
    for (std::size_t pieces : piecesPerChart(triangles, atlas)) EXPECT_EQ(pieces, 1u);
    expectValidAtlas(triangles, atlas, options);
}

TEST(LightmapAtlas, AttachingKeepsMaterialsApartAndChartsWithinTheirExtent) {
    const std::vector<Triangle> triangles = hexagonalPrism(0.4);
    std::vector<std::uint32_t> groups(triangles.size(), 0);
    for (std::size_t t = 12; t < groups.size(); ++t) groups[t] = 1;  // the sides of another material
    ChartOptions options;
    options.attachArea = 1.0;
    options.attachExtent = 8.0;
    const ChartSet set = makeCharts(triangles, groups, options);
    EXPECT_EQ(set.charts.size(), 3u);  // the ends, and the sides unrolled into one band
    for (const FlatChart& chart : set.charts)
        for (std::uint32_t t : chart.triangles) EXPECT_EQ(groups[t], groups[chart.triangles.front()]);
    // Charts no wider than the extent allows: each side alone (1 m wide).
    options.attachExtent = 1.5;
    for (const FlatChart& chart : makeCharts(triangles, groups, options).charts)
        if (groups[chart.triangles.front()] == 1) EXPECT_LE(chart.extent.x, 1.5 + 1e-9);
}

TEST(LightmapAtlas, AChartWiderThanAPageIsCutWithinIt) {
    // A flat strip 12 m long in 96 quads lies flat as one chart, 120 texels long at 0.1 m a
    // texel: more than a page of 64 holds, so it is cut by projection into pieces that fit. The
    // strip begins with a sliver a millionth of a metre across beside a 5 m triangle, which once
    // made the cut's search grid a millionth of a metre fine (minutes and gigabytes).
    std::vector<Triangle> triangles;
    const double t = 1e-6;
    triangles.push_back({glm::dvec3(0, 0, 0), glm::dvec3(t, 0, 0), glm::dvec3(0, t, 0)});
    triangles.push_back({glm::dvec3(t, 0, 0), glm::dvec3(5, 5, 0), glm::dvec3(0, t, 0)});
    addGrid(triangles, glm::dvec3(0, -1, 0), glm::dvec3(12, 0, 0), glm::dvec3(0, 0.5, 0), 96, 1);
    AtlasOptions options;
    options.texelSize = 0.1;
    options.pageSize = 64;
    options.gutter = 1;
    const Atlas atlas = buildAtlas(triangles, options);
    EXPECT_GE(atlas.charts.size(), 3u);  // 120 texels of strip in pieces of at most 62
    for (const AtlasChart& c : atlas.charts) {
        EXPECT_LE(c.width + 2 * options.gutter, options.pageSize);
        EXPECT_LE(c.height + 2 * options.gutter, options.pageSize);
    }
    expectValidAtlas(triangles, atlas, options);
}

TEST(LightmapAtlas, ChartsThatFillAPageGoOnToTheNext) {
    const std::vector<Triangle> triangles = box(2);
    AtlasOptions options;
    options.texelSize = 1.0 / 100.0;  // faces of 100 x 100 texels
    options.pageSize = 220;           // two 104-texel boxes a row, two rows: four faces a page
    options.gutter = 2;
    const Atlas atlas = buildAtlas(triangles, options);
    EXPECT_EQ(atlas.charts.size(), 6u);
    EXPECT_EQ(atlas.pages, 2u);
    expectValidAtlas(triangles, atlas, options);
}

TEST(LightmapAtlas, DegenerateTrianglesGetAPointOfTheirOwn) {
    std::vector<Triangle> triangles = box(1);
    triangles.push_back({glm::dvec3(0.5, 0.5, 0.5), glm::dvec3(0.6, 0.5, 0.5), glm::dvec3(0.7, 0.5, 0.5)});
    triangles.push_back({glm::dvec3(0.0), glm::dvec3(0.0), glm::dvec3(0.0)});
    AtlasOptions options;
    options.texelSize = 0.05;
    options.pageSize = 128;
    const Atlas atlas = buildAtlas(triangles, options);
    EXPECT_EQ(atlas.charts.size(), 8u);
    EXPECT_EQ(atlas.charts[atlas.chartOf[12]].triangles.size(), 1u);
    EXPECT_EQ(atlas.charts[atlas.chartOf[12]].width, 1u);
    expectValidAtlas(triangles, atlas, options);
}

TEST(LightmapAtlas, RefusesATriangleLargerThanAPageAndBadOptions) {
    const std::vector<Triangle> triangles = box(1);
    AtlasOptions options;
    options.texelSize = 0.01;  // a face is 100 texels
    options.pageSize = 64;
    try {
        buildAtlas(triangles, options);
        FAIL() << "a 100-texel triangle fitted a 64-texel page";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("use a texel size of"), std::string::npos) << e.what();
    }
    options.pageSize = 1024;
    options.texelSize = 0.0;
    EXPECT_THROW(buildAtlas(triangles, options), InputError);
    options.texelSize = std::nan("");
    EXPECT_THROW(buildAtlas(triangles, options), InputError);
    options.texelSize = 0.01;
    options.gutter = 600;
    EXPECT_THROW(buildAtlas(triangles, options), InputError);
}

}  // namespace
}  // namespace rad

namespace rad {
namespace {

using Uv = std::array<glm::dvec2, 3>;

TEST(LightmapUvCheck, ATiledGridIsUsableAndAnOverlapOrAFlatTriangleIsFound) {
    // A 10 x 10 grid of quads over [0, 1]^2, two triangles each: they share edges and corners only.
    std::vector<Uv> uv;
    for (int j = 0; j < 10; ++j)
        for (int i = 0; i < 10; ++i) {
            const glm::dvec2 p(i / 10.0, j / 10.0), q((i + 1) / 10.0, j / 10.0), r(i / 10.0, (j + 1) / 10.0),
                s((i + 1) / 10.0, (j + 1) / 10.0);
            uv.push_back({p, q, s});
            uv.push_back({p, s, r});
        }
    EXPECT_TRUE(checkUvLayout(uv).usable());
    // A copy of triangle 37 moved by a quarter cell overlaps it and its neighbours.
    std::vector<Uv> moved = uv;
    Uv copy = uv[37];
    for (glm::dvec2& p : copy) p += glm::dvec2(0.025, 0.0);
    moved.push_back(copy);
    const UvLayoutCheck overlap = checkUvLayout(moved);
    EXPECT_FALSE(overlap.usable());
    EXPECT_GE(overlap.overlappingPairs, 2u);
    ASSERT_FALSE(overlap.examples.empty());
    bool names37 = false;
    for (const auto& pair : overlap.examples) names37 = names37 || (pair[0] == 37 && pair[1] == 200);
    EXPECT_TRUE(names37);
    // A triangle of no area, and one with a coordinate that is not a number.
    std::vector<Uv> flat = uv;
    flat.push_back({glm::dvec2(0.1, 0.1), glm::dvec2(0.2, 0.2), glm::dvec2(0.3, 0.3)});
    flat.push_back({glm::dvec2(std::nan(""), 0.0), glm::dvec2(0.5, 0.5), glm::dvec2(0.5, 0.6)});
    const UvLayoutCheck degenerate = checkUvLayout(flat);
    EXPECT_EQ(degenerate.degenerate, 2u);
    EXPECT_EQ(degenerate.overlappingPairs, 0u);
    EXPECT_FALSE(degenerate.usable());
}

TEST(LightmapUvCheck, AnAtlasItBuiltPassesItsCheckAndAMirroredCopyFails) {
    const std::vector<Triangle> triangles = box(3);
    AtlasOptions options;
    options.texelSize = 0.02;
    options.pageSize = 256;
    const Atlas atlas = buildAtlas(triangles, options);
    ASSERT_EQ(atlas.pages, 1u);
    std::vector<Uv> uv(atlas.texels.size());
    for (std::size_t t = 0; t < uv.size(); ++t)
        for (int k = 0; k < 3; ++k) uv[t][k] = atlas.texels[t][k] / double(atlas.pageSize);
    EXPECT_TRUE(checkUvLayout(uv).usable());
    // Two charts given the same place: every triangle of one overlaps triangles of the other.
    const AtlasChart &a = atlas.charts[0], &b = atlas.charts[1];
    std::vector<Uv> stacked = uv;
    for (std::uint32_t t : b.triangles)
        for (glm::dvec2& p : stacked[t]) p += glm::dvec2(double(a.x) - b.x, double(a.y) - b.y) / double(atlas.pageSize);
    EXPECT_GE(checkUvLayout(stacked).overlappingPairs, b.triangles.size());
}

}  // namespace
}  // namespace rad
