// Small patches receive in clusters (solver/cluster_receivers.h): where the elements of a cluster
// agree with its light within their Poisson noise they share it; where they do not, they keep their
// own; and the power the shots brought is kept, cluster by cluster and channel by channel.

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "mesh/elements.h"
#include "mesh/mesh.h"
#include "mesh/patch_clusters.h"
#include "scene/gltf_loader.h"
#include "solver/cluster_receivers.h"
#include "test_support.h"

namespace rad {
namespace {

// The white furnace with each face cut into 16 x 16 quads, at a patch size of 0.25 m: 3,072
// triangles of equal area, one element each, in 216 clusters of about 14 (test_patch_clusters).
struct CutFurnace {
    Mesh mesh = buildMesh(loadGltf(test::sourcePath("tests/data/solve/white-furnace-cut.gltf")), {0.25, 10'000'000});
    ElementMesh elements = ElementMesh::uniform(mesh, 0.0);
    PatchClusters clusters = PatchClusters::of(mesh);
};

// Each hit carries this power; its channels sum to one, so hits = power summed / 1.
const glm::dvec3 kRay(0.5, 0.3, 0.2);

std::vector<glm::dvec3> poissonHits(std::size_t count, double mean, std::uint32_t seed) {
    std::mt19937 random(seed);
    std::poisson_distribution<int> hits(mean);
    std::vector<glm::dvec3> shot(count);
    for (glm::dvec3& s : shot) s = kRay * static_cast<double>(hits(random));
    return shot;
}

// The elements of cluster c.
std::vector<std::uint32_t> elementsOf(const CutFurnace& f, std::size_t c) {
    std::vector<std::uint32_t> out;
    const auto& start = f.elements.elementStart();
    for (std::uint32_t m = f.clusters.start()[c]; m < f.clusters.start()[c + 1]; ++m)
        for (std::uint32_t e = start[f.clusters.members()[m]]; e < start[f.clusters.members()[m] + 1]; ++e)
            out.push_back(e);
    return out;
}

TEST(ClusterReceivers, UniformLightWithFewHitsIsPooledAndKeepsItsPower) {
    // Every element's hits are Poisson with mean 2: its own estimate is off by 1/sqrt(2) = 71 %
    // RMS, a cluster of n elements' mean by 1/sqrt(2 n), about 19 % for n = 14. The test keeps an
    // element of k hits against k^ = 2 where |k - 2| <= 3 sqrt(2) + 1, k <= 7: P(k >= 8) = 0.1 %.
    const CutFurnace f;
    ASSERT_EQ(f.elements.elements().size(), 3072u);
    const std::vector<glm::dvec3> shot = poissonHits(3072, 2.0, 1);
    const PooledReceivers pooled = poolReceivers(f.elements, f.clusters, shot, 1.0);
    EXPECT_GT(pooled.pooled, 3000u);
    double ownError = 0.0, pooledError = 0.0;
    for (std::size_t e = 0; e < shot.size(); ++e) {
        ownError += std::pow(shot[e].x / kRay.x - 2.0, 2);
        pooledError += std::pow(pooled.power[e].x / kRay.x - 2.0, 2);
    }
    ownError = std::sqrt(ownError / 3072) / 2.0;
    pooledError = std::sqrt(pooledError / 3072) / 2.0;
    // Over 3,072 elements these RMS figures are known to a few per cent of themselves.
    EXPECT_NEAR(ownError, std::sqrt(0.5), 0.05);
    EXPECT_LT(pooledError, 0.3);
    for (std::size_t c = 0; c < f.clusters.count(); ++c) {
        glm::dvec3 before(0.0), after(0.0);
        double hits = 0.0;
        for (const std::uint32_t e : elementsOf(f, c)) {
            before += shot[e];
            after += pooled.power[e];
            hits += shot[e].x / kRay.x;
        }
        for (int k = 0; k < 3; ++k) ASSERT_NEAR(after[k], before[k], 1e-12 * (1.0 + before[k])) << "cluster " << c;
        // An element's value rests on the hits of the elements it was pooled with: all of them
        // where every element agreed.
        const std::vector<std::uint32_t> members = elementsOf(f, c);
        bool all = true;
        for (const std::uint32_t e : members) all = all && pooled.power[e] == pooled.power[members.front()];
        if (all) {
            for (const std::uint32_t e : members) ASSERT_DOUBLE_EQ(pooled.hits[e], hits);
        }
    }
}

TEST(ClusterReceivers, ABrightElementKeepsItsOwnLight) {
    // One element of a cluster holds a bright spot (100 hits where its neighbours have about 2):
    // it keeps its own power, and the others share theirs without it (their mean stays near 2
    // rather than rising by 100 / 14 = 7 hits each).
    const CutFurnace f;
    std::vector<glm::dvec3> shot = poissonHits(3072, 2.0, 2);
    const std::vector<std::uint32_t> members = elementsOf(f, 17);
    ASSERT_GE(members.size(), 8u);
    const std::uint32_t bright = members[members.size() / 2];
    shot[bright] = kRay * 100.0;
    const PooledReceivers pooled = poolReceivers(f.elements, f.clusters, shot, 1.0);
    EXPECT_EQ(pooled.power[bright], shot[bright]);
    EXPECT_DOUBLE_EQ(pooled.hits[bright], 100.0);
    double others = 0.0;
    std::size_t count = 0;
    for (const std::uint32_t e : members) {
        if (e == bright) continue;
        others += pooled.power[e].x / kRay.x;
        ++count;
    }
    // The others' mean: 2 hits, sigma sqrt(2 / 13) = 0.39; 5 sigma.
    EXPECT_NEAR(others / count, 2.0, 5.0 * std::sqrt(2.0 / count));
}

TEST(ClusterReceivers, MoreHitsResolveTheLightsChanges) {
    // A gradient along x across every face but the two normal to x: hits n (1 + 1.2 x), x from
    // -0.5 to 0.5, so across a cluster's 0.177 m cell they change by 21 % of n. At n = 500 that
    // is within an element's Poisson band (3 sqrt(500) + 1 = 68 hits either side of the mean) and
    // the clusters pool; as n grows the band grows as sqrt(n) and the change as n, so fewer and
    // fewer elements are pooled: the result converges to the elements' own. An element is never
    // moved by more than twice its band (its own value and the pool's both lie within it).
    const CutFurnace f;
    std::size_t last = f.elements.elements().size() + 1;
    for (const double n : {500.0, 5'000.0, 50'000.0}) {
        std::vector<glm::dvec3> shot(3072);
        for (std::size_t e = 0; e < shot.size(); ++e) {
            const auto& p = f.elements.elements()[e].p;
            const double x = (p[0].x + p[1].x + p[2].x) / 3.0;
            shot[e] = kRay * std::round(n * (1.0 + 1.2 * x));
        }
        const PooledReceivers pooled = poolReceivers(f.elements, f.clusters, shot, 1.0);
        std::size_t changed = 0;
        for (std::size_t c = 0; c < f.clusters.count(); ++c) {
            const std::vector<std::uint32_t> members = elementsOf(f, c);
            double mean = 0.0;
            for (const std::uint32_t e : members) mean += shot[e].x / kRay.x / members.size();
            for (const std::uint32_t e : members) {
                const double moved = std::fabs(pooled.power[e].x - shot[e].x) / kRay.x;
                EXPECT_LE(moved, 2.0 * (3.0 * std::sqrt(mean) + 1.0) + 1e-9) << "element " << e;
                changed += moved > 1e-9 * n;
            }
        }
        EXPECT_LT(changed, last) << n << " hits an element";
        last = changed;
    }
    // At 50,000 hits (band 1.3 %, change 21 %) almost every element keeps its own.
    EXPECT_LT(last, 3072u / 10);
}

TEST(ClusterReceivers, LightThatVariesWithinItsNoiseIsPooledByHowMuchItVaries) {
    // True hits t = n (1 + 1.2 x) along x (21 % of n across a cluster's cell), drawn as Poisson
    // counts. At n = 300 an element's own value is off by sqrt(300) = 17 hits RMS and the
    // cluster's flat mean by about as much (the gradient's 0.21 n / sqrt(12) = 18 on the faces it
    // crosses): both are inside the 3 sigma band, so only the shrinkage decides. Shrunk by the
    // variance the counts show, the result must beat both, over every element of the four
    // faces the gradient crosses (2,048 elements: each RMS figure is known to about 2 %).
    const CutFurnace f;
    std::mt19937 random(5);
    std::vector<glm::dvec3> shot(3072);
    std::vector<double> truth(3072);
    for (std::size_t e = 0; e < shot.size(); ++e) {
        const auto& p = f.elements.elements()[e].p;
        truth[e] = 300.0 * (1.0 + 1.2 * (p[0].x + p[1].x + p[2].x) / 3.0);
        shot[e] = kRay * static_cast<double>(std::poisson_distribution<int>(truth[e])(random));
    }
    const PooledReceivers pooled = poolReceivers(f.elements, f.clusters, shot, 1.0);
    double own = 0.0, flat = 0.0, shrunk = 0.0, power = 0.0, kept = 0.0;
    std::size_t count = 0;
    for (std::size_t c = 0; c < f.clusters.count(); ++c) {
        const std::vector<std::uint32_t> members = elementsOf(f, c);
        const auto& p = f.elements.elements()[members.front()].p;
        if (std::fabs(p[0].x - p[1].x) + std::fabs(p[0].x - p[2].x) < 1e-6) continue;  // a face normal to x
        double mean = 0.0;
        for (const std::uint32_t e : members) mean += shot[e].x / kRay.x / members.size();
        for (const std::uint32_t e : members) {
            own += std::pow(shot[e].x / kRay.x - truth[e], 2);
            flat += std::pow(mean - truth[e], 2);
            shrunk += std::pow(pooled.power[e].x / kRay.x - truth[e], 2);
            power += shot[e].y;
            kept += pooled.power[e].y;
            ++count;
        }
    }
    ASSERT_EQ(count, 2048u);
    EXPECT_LT(shrunk, 0.9 * own);
    EXPECT_LT(shrunk, 0.9 * flat);
    EXPECT_NEAR(kept, power, 1e-9 * power);
}

TEST(ClusterReceivers, ClustersOfOneAndNoRaysChangeNothing) {
    const CutFurnace f;
    const std::vector<glm::dvec3> shot = poissonHits(3072, 2.0, 3);
    const PooledReceivers none = poolReceivers(f.elements, f.clusters, shot, 0.0);
    EXPECT_EQ(none.power, shot);
    EXPECT_EQ(none.pooled, 0u);
    const PooledReceivers alone =
        poolReceivers(f.elements, PatchClusters::identity(f.mesh.patches.size()), shot, 1.0);
    EXPECT_EQ(alone.power, shot);
    EXPECT_EQ(alone.pooled, 0u);
    EXPECT_DOUBLE_EQ(alone.hits[5], shot[5].x / kRay.x);
}

}  // namespace
}  // namespace rad
