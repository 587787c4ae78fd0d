#pragma once
// A binary BVH built with the binned surface-area heuristic. It is only an intermediate:
// wide_bvh.h collapses it into the 8-wide layout the kernels trace.

#include <cstdint>
#include <vector>

#include "scene/scene.h"

namespace rad {

struct BinaryBvhNode {
    Bounds box;
    std::int32_t left = -1, right = -1;     // children (inner node); -1 in a leaf
    std::uint32_t first = 0, count = 0;     // leaf: primitives order[first .. first + count)

    bool isLeaf() const { return left < 0; }
};

struct BinaryBvh {
    std::vector<BinaryBvhNode> nodes;       // nodes[0] is the root
    std::vector<std::uint32_t> order;       // primitive indices, grouped by leaf
};

// Builds over primitives given by their boxes. Leaves hold at most maxLeafSize primitives.
BinaryBvh buildBinaryBvh(const std::vector<Bounds>& boxes, std::uint32_t maxLeafSize);

}  // namespace rad
