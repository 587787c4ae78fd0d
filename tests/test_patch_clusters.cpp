// Clusters of small patches (mesh/patch_clusters.h): which patches shoot together.

#include <algorithm>
#include <cmath>
#include <set>

#include <gtest/gtest.h>

#include "mesh/mesh.h"
#include "mesh/patch_clusters.h"
#include "scene/gltf_loader.h"
#include "test_support.h"

namespace rad {
namespace {

Mesh meshOf(const std::string& file, double patchSize) {
    return buildMesh(loadGltf(test::sourcePath(file)), {patchSize, 10'000'000});
}

glm::dvec3 centre(const Patch& p) {
    return (glm::dvec3(p.p[0]) + glm::dvec3(p.p[1]) + glm::dvec3(p.p[2])) / 3.0;
}

TEST(PatchClusters, ASceneOfLargeFacesClustersAsTheIdentity) {
    // The Cornell box's faces are all larger than its patches: every patch shoots on its own,
    // and the solve is the one it was before clusters (tests/regression holds its bits).
    const Mesh mesh = meshOf("scenes/cornell-box.gltf", 0.0);
    const PatchClusters clusters = PatchClusters::of(mesh);
    EXPECT_TRUE(clusters.isIdentity());
    ASSERT_EQ(clusters.count(), mesh.patches.size());
    for (std::size_t c = 0; c < clusters.count(); ++c) ASSERT_EQ(clusters.members()[clusters.start()[c]], c);
}

TEST(PatchClusters, SmallPatchesClusterByPlaceFacingAndMaterial) {
    // The white furnace with each unit face cut into 16 x 16 quads: 3,072 triangles, each a patch
    // under the patch size of 0.25 m (their longest edge, 0.088 m, is under half of it). The
    // cells are 0.25 / sqrt(2) = 0.177 m wide, so each face's 1 m spans 6 of them in each
    // direction: 36 clusters a face, 216 in all (the cube is centred on the origin, and no cell
    // boundary falls on a triangle's centre).
    const Mesh mesh = meshOf("tests/data/solve/white-furnace-cut.gltf", 0.25);
    ASSERT_EQ(mesh.patches.size(), 3072u);
    const PatchClusters clusters = PatchClusters::of(mesh);
    EXPECT_FALSE(clusters.isIdentity());
    EXPECT_EQ(clusters.count(), 216u);
    std::set<std::uint32_t> seen;
    const double cell = 0.25 / std::sqrt(2.0);
    for (std::size_t c = 0; c < clusters.count(); ++c) {
        ASSERT_LT(clusters.start()[c], clusters.start()[c + 1]);
        ASSERT_LE(clusters.size(c), PatchClusters::kMaxMembers);
        const Patch& first = mesh.patches[clusters.members()[clusters.start()[c]]];
        glm::dvec3 lo(1e9), hi(-1e9);
        for (std::uint32_t m = clusters.start()[c]; m < clusters.start()[c + 1]; ++m) {
            const std::uint32_t p = clusters.members()[m];
            ASSERT_TRUE(seen.insert(p).second) << "patch " << p << " is in two clusters";
            if (m > clusters.start()[c]) ASSERT_LT(clusters.members()[m - 1], p);  // increasing
            const Patch& patch = mesh.patches[p];
            EXPECT_EQ(patch.surface, first.surface);
            EXPECT_EQ(patch.material, first.material);
            EXPECT_GT(glm::dot(patch.normal, first.normal), 0.999f);  // one flat face here
            lo = glm::min(lo, centre(patch));
            hi = glm::max(hi, centre(patch));
        }
        for (int k = 0; k < 3; ++k) EXPECT_LT(hi[k] - lo[k], cell) << "cluster " << c << " spans more than a cell";
        if (c > 0) ASSERT_LT(clusters.members()[clusters.start()[c - 1]], clusters.members()[clusters.start()[c]]);
    }
    EXPECT_EQ(seen.size(), mesh.patches.size());
    // At the default patch size (1/32 of the diagonal, 0.054 m) the same triangles are no
    // smaller than half a patch: each shoots on its own.
    EXPECT_TRUE(PatchClusters::of(meshOf("tests/data/solve/white-furnace-cut.gltf", 0.0)).isIdentity());
}

}  // namespace
}  // namespace rad
