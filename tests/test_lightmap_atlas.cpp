// The lightmap atlas (host/lightmap/chart_atlas.h): charts that do not overlap and keep their
// gutters, one texel size everywhere up to the stated stretch, and clear refusals.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

#include "lightmap/chart_atlas.h"
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
        for (const glm::dvec2& p : atlas.texels[t]) {
            EXPECT_GE(p.x, c.x - slack) << "triangle " << t;
            EXPECT_LE(p.x, c.x + c.width + slack) << "triangle " << t;
            EXPECT_GE(p.y, c.y - slack) << "triangle " << t;
            EXPECT_LE(p.y, c.y + c.height + slack) << "triangle " << t;
        }
        const glm::dvec3 n = glm::cross(triangles[t][1] - triangles[t][0], triangles[t][2] - triangles[t][0]);
        const double surface = 0.5 * glm::length(n) / (options.texelSize * options.texelSize);
        const double texels = flatArea(atlas.texels[t]);
        EXPECT_LE(texels, surface * (1.0 + 1e-9)) << "triangle " << t;
        EXPECT_GE(texels * atlas.largestStretch, surface * (1.0 - 1e-9)) << "triangle " << t;
    }
    EXPECT_LE(atlas.largestStretch, 1.0 / std::cos(options.coneDegrees * 3.14159265358979 / 180.0) + 1e-9);
    const long g = atlas.gutter;
    for (std::size_t i = 0; i < atlas.charts.size(); ++i) {
        const AtlasChart& a = atlas.charts[i];
        EXPECT_LT(a.page, atlas.pages);
        EXPECT_GE(long(a.x), g);
        EXPECT_GE(long(a.y), g);
        EXPECT_LE(long(a.x + a.width) + g, long(atlas.pageSize));
        EXPECT_LE(long(a.y + a.height) + g, long(atlas.pageSize));
        for (std::size_t j = i + 1; j < atlas.charts.size(); ++j) {
            const AtlasChart& b = atlas.charts[j];
            if (a.page != b.page) continue;
            const bool apart = long(a.x + a.width) + 2 * g <= long(b.x) || long(b.x + b.width) + 2 * g <= long(a.x) ||
                               long(a.y + a.height) + 2 * g <= long(b.y) || long(b.y + b.height) + 2 * g <= long(a.y);
            EXPECT_TRUE(apart) << "charts " << i << " and " << j << " are closer than two gutters";
        }
    }
    // Coverage at 4 x 4 samples per texel over every page: no sample inside two triangles.
    for (std::uint32_t page = 0; page < atlas.pages; ++page) {
        std::vector<std::uint8_t> covered(std::size_t(atlas.pageSize) * atlas.pageSize * 16, 0);
        for (std::size_t t = 0; t < triangles.size(); ++t) {
            if (atlas.charts[atlas.chartOf[t]].page != page) continue;
            const auto& f = atlas.texels[t];
            const int x0 = std::max(0, int(std::floor(std::min({f[0].x, f[1].x, f[2].x}) * 4)));
            const int x1 =
                std::min(int(atlas.pageSize) * 4 - 1, int(std::ceil(std::max({f[0].x, f[1].x, f[2].x}) * 4)));
            const int y0 = std::max(0, int(std::floor(std::min({f[0].y, f[1].y, f[2].y}) * 4)));
            const int y1 =
                std::min(int(atlas.pageSize) * 4 - 1, int(std::ceil(std::max({f[0].y, f[1].y, f[2].y}) * 4)));
            for (int y = y0; y <= y1; ++y)
                for (int x = x0; x <= x1; ++x)
                    if (strictlyInside(f, glm::dvec2((x + 0.5) / 4.0, (y + 0.5) / 4.0), 1e-9)) {
                        std::uint8_t& c = covered[std::size_t(y) * atlas.pageSize * 4 + x];
                        EXPECT_EQ(c, 0) << "page " << page << " sample (" << x << ", " << y << ") covered twice";
                        if (c != 0) return;
                        c = 1;
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
    // Faces meet at 90 degrees, far outside the 15-degree cone: six flat charts of 60 x 60 texels.
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

TEST(LightmapAtlas, ACurvedSurfaceSplitsWhereItsNormalsLeaveTheCone) {
    // A quarter cylinder of radius 1 in 36 facets (2.5 degrees each) by 4 along its axis.
    std::vector<Triangle> triangles;
    const int facets = 36;
    for (int i = 0; i < facets; ++i)
        for (int j = 0; j < 4; ++j) {
            const double a0 = 0.5 * 3.14159265358979 * i / facets, a1 = 0.5 * 3.14159265358979 * (i + 1) / facets;
            const glm::dvec3 p(std::cos(a0), std::sin(a0), 0.25 * j), q(std::cos(a1), std::sin(a1), 0.25 * j);
            const glm::dvec3 up(0, 0, 0.25);
            triangles.push_back({p, p + up, q});
            triangles.push_back({q, p + up, q + up});
        }
    AtlasOptions options;
    options.texelSize = 0.01;
    options.pageSize = 512;
    const Atlas atlas = buildAtlas(triangles, options);
    // 90 degrees of turn in charts whose normals stay within 15 degrees of their first one's:
    // each chart spans at most 30 degrees (seven facets from a first one at its edge), so at
    // least three charts, and the stretch stays within 1 / cos(15 degrees).
    EXPECT_GE(atlas.charts.size(), 3u);
    EXPECT_LE(atlas.charts.size(), 12u);
    EXPECT_GT(atlas.largestStretch, 1.0 + 1e-6);  // curved charts do stretch
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
