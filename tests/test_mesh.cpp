// Patches: the regular grid, the patch-size rule, sides of double-sided faces.

#include <algorithm>
#include <random>
#include <set>

#include <gtest/gtest.h>

#include "mesh/mesh.h"
#include "mesh/patch_grid.h"
#include "mesh/sampling_tables.h"
#include "util/shares.h"
#include "scene/gltf_loader.h"
#include "test_support.h"
#include "util/error.h"

namespace rad {
namespace {

double area(const std::array<glm::vec3, 3>& p) {
    return 0.5 * glm::length(glm::cross(glm::dvec3(p[1]) - glm::dvec3(p[0]), glm::dvec3(p[2]) - glm::dvec3(p[0])));
}

TEST(PatchGrid, CellsAreIndexedInOrderAndTileTheTriangle) {
    const std::array<glm::vec3, 3> t{glm::vec3(0, 0, 0), glm::vec3(3, 0, 0), glm::vec3(1, 2, 0)};
    for (std::uint32_t n = 1; n <= 7; ++n) {
        std::uint32_t expected = 0;
        double total = 0.0;
        forEachGridCell(n, [&](GridCell c) {
            EXPECT_EQ(gridIndex(n, c), expected++) << "n=" << n;
            const auto corners = gridCellCorners(t, n, c);
            total += area(corners);
            // Same orientation as the parent triangle.
            const glm::vec3 normal = glm::cross(corners[1] - corners[0], corners[2] - corners[0]);
            EXPECT_GT(normal.z, 0.0f);
        });
        EXPECT_EQ(expected, n * n);
        EXPECT_NEAR(total, area(t), 1e-7 * area(t));  // corners are floats
    }
}

TEST(Mesh, NoPatchEdgeExceedsThePatchSize) {
    const Scene scene = loadGltf(test::sourcePath("scenes/cornell-box.gltf"));
    const double size = 0.05;
    const Mesh mesh = buildMesh(scene, {size, 10'000'000});
    EXPECT_GT(mesh.patches.size(), 1000u);
    double total = 0.0, sceneArea = 0.0;
    for (const Patch& p : mesh.patches) {
        for (int k = 0; k < 3; ++k) EXPECT_LE(glm::length(p.p[(k + 1) % 3] - p.p[k]), size * (1 + 1e-6));
        total += p.area;
    }
    for (const Surface& s : scene.surfaces) sceneArea += test::surfaceArea(s);
    EXPECT_NEAR(total, sceneArea, 1e-5 * sceneArea);
}

TEST(Mesh, SurfacesOwnContiguousPatches) {
    const Scene scene = loadGltf(test::sourcePath("scenes/cornell-box.gltf"));
    const Mesh mesh = buildMesh(scene, {0.1, 10'000'000});
    ASSERT_EQ(mesh.surfaces.size(), scene.surfaces.size());
    std::uint32_t next = 0;
    for (std::uint32_t s = 0; s < mesh.surfaces.size(); ++s) {
        EXPECT_EQ(mesh.surfaces[s].firstPatch, next);
        EXPECT_EQ(mesh.surfaces[s].name, scene.surfaces[s].name);
        for (std::uint32_t k = 0; k < mesh.surfaces[s].patchCount; ++k)
            EXPECT_EQ(mesh.patches[next + k].surface, s);
        next += mesh.surfaces[s].patchCount;
    }
    EXPECT_EQ(next, mesh.patches.size());
}

TEST(Mesh, EachSurfaceRunsGuideBracketsTheTrianglesItsCoordinatesFallOn) {
    // The area tables' guides (util/shares.h: shareGuide) lie after every triangle's entry, and
    // for any coordinate x of a run's table, the entries of x's part and of the next part
    // bracket the triangle x falls on (the first whose end lies past x), which is where a ray's
    // search looks (kernels/ray_source.h).
    const Scene scene = loadGltf(test::sourcePath("scenes/cornell-box-specular.gltf"));
    const Mesh mesh = buildMesh(scene, {0.1, 10'000'000});
    const SamplingTables tables = buildSamplingTables(mesh);
    std::mt19937 random(3);
    int runs = 0;
    std::uint32_t largest = 0;
    for (const TriangleRun& run : tables.surfaceRuns) {
        if (run.count <= 1) continue;
        ++runs;
        largest = std::max(largest, run.count);
        const unsigned bits = guideBits(run.count);
        ASSERT_GE(run.guide, tables.triangles.size());
        ASSERT_LE(run.guide + (std::size_t{1} << bits), tables.cdf.size());
        const auto ends = tables.cdf.begin() + run.first;
        for (int i = 0; i < 2000; ++i) {
            const auto x = static_cast<std::uint32_t>(random());
            const auto k = static_cast<std::uint32_t>(std::upper_bound(ends, ends + (run.count - 1), x) - ends);
            const std::uint32_t part = x >> (32 - bits);
            const std::uint32_t lo = tables.cdf[run.guide + part];
            const std::uint32_t hi = part + 1 < (1u << bits) ? tables.cdf[run.guide + part + 1] : run.count - 1;
            EXPECT_LE(lo, k);
            EXPECT_GE(hi, k);
        }
    }
    EXPECT_GT(runs, 0);
    EXPECT_GT(largest, 100u);  // the glass sphere's triangles, of uneven areas
}

TEST(Mesh, DoubleSidedFacesGetABackSide) {
    const Scene scene = loadGltf(test::sourcePath("tests/data/gltf/double-sided.gltf"));
    const Mesh mesh = buildMesh(scene, {0.3, 10'000'000});
    std::set<std::string> names;
    for (const MeshSurface& s : mesh.surfaces) names.insert(s.name);
    EXPECT_EQ(names, (std::set<std::string>{"plate", "plate:back", "above", "below"}));
    for (const MeshSurface& s : mesh.surfaces) {
        EXPECT_NEAR(s.area, 1.0, 1e-6) << s.name;
        for (std::uint32_t k = 0; k < s.patchCount; ++k) {
            const Patch& p = mesh.patches[s.firstPatch + k];
            const glm::vec3 n = glm::cross(p.p[1] - p.p[0], p.p[2] - p.p[0]);
            EXPECT_GT(glm::dot(n, p.normal), 0.0f) << s.name;  // winding agrees with the side's normal
            if (s.name == "plate") EXPECT_NEAR(p.normal.y, 1.0f, 1e-6);
            if (s.name == "plate:back") EXPECT_NEAR(p.normal.y, -1.0f, 1e-6);
        }
    }
    for (const Face& f : mesh.faces) {
        const bool plate = mesh.patches[f.frontPatch].surface == 0;
        EXPECT_EQ(f.backPatch != kNoPatch, plate);
    }
}

TEST(Mesh, RefusesMoreThanMaxPatches) {
    const Scene scene = loadGltf(test::sourcePath("scenes/cornell-box.gltf"));
    try {
        buildMesh(scene, {0.001, 100'000});
        FAIL() << "a mesh of millions of patches was built";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("--max-patches"), std::string::npos) << e.what();
    }
    EXPECT_THROW(buildMesh(scene, {-1.0, 100}), InputError);
}

}  // namespace
}  // namespace rad
