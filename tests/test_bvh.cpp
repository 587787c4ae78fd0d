// The wide BVH: every face in exactly one leaf lane, boxes that contain their subtrees, a
// bounded traversal stack.

#include <random>

#include <gtest/gtest.h>

#include "bvh/wide_bvh.h"

namespace rad {
namespace {

std::vector<Face> randomFaces(std::size_t count, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> position(-10.0f, 10.0f), offset(-0.5f, 0.5f);
    std::vector<Face> faces(count);
    for (Face& f : faces) {
        const glm::vec3 c(position(rng), position(rng), position(rng));
        for (auto& p : f.p) p = c + glm::vec3(offset(rng), offset(rng), offset(rng));
    }
    return faces;
}

struct Box {
    glm::vec3 lo, hi;
};

// Checks the subtree under `node` against `box` and records its faces.
void checkSubtree(const WideBvh& bvh, const std::vector<Face>& faces, std::int32_t entry, const Box& box,
                  std::vector<int>& seen) {
    auto inside = [&](const glm::vec3& p) {
        return glm::all(glm::greaterThanEqual(p, box.lo)) && glm::all(glm::lessThanEqual(p, box.hi));
    };
    if (entry < 0) {
        const int count = RAD_LEAF_COUNT(entry);
        ASSERT_LE(static_cast<std::size_t>(RAD_LEAF_FIRST(entry)) + count, bvh.blocks.size());
        for (int k = 0; k < count; ++k) {
            const LeafBlock& block = bvh.blocks[static_cast<std::size_t>(RAD_LEAF_FIRST(entry)) + k];
            EXPECT_GE(block.face[0], 0) << "a leaf's block holds nothing";
            // Faces are packed: only a run's last block may have empty lanes.
            if (k + 1 < count) EXPECT_GE(block.face[RAD_LEAF_SIZE - 1], 0) << "a partly empty block inside a run";
            for (int lane = 0; lane < RAD_LEAF_SIZE; ++lane) {
                if (block.face[lane] < 0) continue;
                const Face& f = faces[static_cast<std::size_t>(block.face[lane])];
                ++seen[static_cast<std::size_t>(block.face[lane])];
                for (int v = 0; v < 3; ++v) {
                    EXPECT_TRUE(inside(f.p[v]));
                    for (int axis = 0; axis < 3; ++axis) EXPECT_EQ(block.v[v][axis][lane], f.p[v][axis]);
                }
            }
        }
        return;
    }
    const BvhNode& node = bvh.nodes[static_cast<std::size_t>(entry)];
    for (int slot = 0; slot < RAD_BVH_WIDTH; ++slot) {
        Box child{{node.lo[0][slot], node.lo[1][slot], node.lo[2][slot]}, {node.hi[0][slot], node.hi[1][slot], node.hi[2][slot]}};
        if (node.child[slot] == RAD_EMPTY_CHILD) {
            EXPECT_GT(child.lo.x, child.hi.x);  // inverted: no ray enters
            continue;
        }
        EXPECT_TRUE(inside(child.lo) && inside(child.hi)) << "child box outside its parent";
        checkSubtree(bvh, faces, node.child[slot], child, seen);
    }
}

void checkTree(const std::vector<Face>& faces) {
    const WideBvh bvh = buildWideBvh(faces);
    std::vector<int> seen(faces.size(), 0);
    const float big = 1e30f;
    checkSubtree(bvh, faces, 0, Box{glm::vec3(-big), glm::vec3(big)}, seen);
    for (std::size_t f = 0; f < faces.size(); ++f) EXPECT_EQ(seen[f], 1) << "face " << f;
    EXPECT_LE(bvh.stackNeeded, static_cast<std::uint32_t>(RAD_STACK_SIZE));
}

TEST(WideBvh, HoldsEveryFaceOnceInsideItsBoxes) {
    for (std::size_t count : {1u, 3u, 4u, 5u, 9u, 100u, 5000u}) checkTree(randomFaces(count, static_cast<std::uint32_t>(count)));
}

TEST(WideBvh, CoincidentFacesStillSplit) {
    std::vector<Face> faces(1000);
    for (Face& f : faces) f.p = {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0)};
    checkTree(faces);
}

TEST(WideBvh, NodesAreEightWideWhereTheTreeAllows) {
    const WideBvh bvh = buildWideBvh(randomFaces(4096, 7));
    std::size_t used = 0;
    for (const BvhNode& n : bvh.nodes)
        for (int slot = 0; slot < RAD_BVH_WIDTH; ++slot) used += n.child[slot] != RAD_EMPTY_CHILD;
    // Collapsing widens nodes: a binary tree would have exactly 2 children per node.
    EXPECT_GT(static_cast<double>(used) / bvh.nodes.size(), 3.0);
}

// A tessellated wall, the usual radiosity mesh: small subtrees at the bottom of the tree become
// runs of leaf blocks, not nodes over two or three small leaves, which had been half of all
// nodes (4.0 children per node on a Cornell box of 16k faces; 7.5 with runs).
TEST(WideBvh, SmallSubtreesBecomeLeavesNotThinNodes) {
    std::vector<Face> faces;
    const int n = 64;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const glm::vec3 p(float(i), float(j), 0.0f);
            faces.push_back({{p, p + glm::vec3(1, 0, 0), p + glm::vec3(1, 1, 0)}});
            faces.push_back({{p, p + glm::vec3(1, 1, 0), p + glm::vec3(0, 1, 0)}});
        }
    checkTree(faces);
    const WideBvh bvh = buildWideBvh(faces);
    std::size_t used = 0, runs = 0;
    for (const BvhNode& node : bvh.nodes)
        for (int slot = 0; slot < RAD_BVH_WIDTH; ++slot) {
            used += node.child[slot] != RAD_EMPTY_CHILD;
            runs += node.child[slot] < 0 && RAD_LEAF_COUNT(node.child[slot]) > 1;
        }
    EXPECT_GT(static_cast<double>(used) / bvh.nodes.size(), 6.0);
    EXPECT_GT(runs, 0u);  // checkTree checked that only a run's last block has empty lanes
}

}  // namespace
}  // namespace rad
