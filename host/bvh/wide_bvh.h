#pragma once
// The BVH the kernels trace: a binned-SAH binary BVH over faces collapsed into 8-wide nodes
// whose children's boxes lie side by side (one float8 per bound), with leaves that are runs of
// one to four blocks of four faces, each block laid out for one float4 triangle test (which
// subtrees become leaves: wide_bvh.cpp). The layout structs are in
// kernels/shared_types.h. This layout traced about twice as many rays per second on PoCL as a
// binary BVH in the measurements of ../shared/NOTES-opencl-pocl.md; bench/rays measures ours.

#include <cstdint>
#include <vector>

#include "mesh/mesh.h"
#include "shared_types.h"

namespace rad {

struct WideBvh {
    std::vector<BvhNode> nodes;     // nodes[0] is the root (always an inner node)
    std::vector<LeafBlock> blocks;
    std::uint32_t stackNeeded = 0;  // worst-case traversal stack entries; <= RAD_STACK_SIZE
    std::uint32_t binaryDepth = 0;
};

// Throws RuntimeFailure if the tree could overflow the kernels' traversal stack.
WideBvh buildWideBvh(const std::vector<Face>& faces);

}  // namespace rad
