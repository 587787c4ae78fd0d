#include "bvh/wide_bvh.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "bvh/binary_bvh.h"
#include "util/error.h"

// A leaf link keeps the run's length in its two low bits and is negative for every block index.
static_assert(RAD_MAX_LEAF_BLOCKS >= 1 && RAD_MAX_LEAF_BLOCKS <= 4, "a leaf link holds 1 to 4 blocks");
static_assert(RAD_LEAF_LINK(RAD_MAX_LEAF_BLOCK - 1u, 4u) < 0, "leaf links are negative");
static_assert(RAD_LEAF_FIRST(RAD_LEAF_LINK(RAD_MAX_LEAF_BLOCK - 1u, 4u)) == RAD_MAX_LEAF_BLOCK - 1u &&
                  RAD_LEAF_COUNT(RAD_LEAF_LINK(RAD_MAX_LEAF_BLOCK - 1u, 4u)) == 4 &&
                  RAD_LEAF_FIRST(RAD_LEAF_LINK(0u, 1u)) == 0 && RAD_LEAF_COUNT(RAD_LEAF_LINK(0u, 1u)) == 1,
              "leaf links round-trip");

namespace rad {
namespace {

// Child boxes grow by a few float ulps of their largest coordinate so that rounding in the
// kernels' slab test never rejects a ray that touches a face on the box's boundary (a closed
// scene must not leak rays between boxes).
Bounds padded(const Bounds& b) {
    const float scale = std::max({std::fabs(b.lo.x), std::fabs(b.lo.y), std::fabs(b.lo.z), std::fabs(b.hi.x),
                                  std::fabs(b.hi.y), std::fabs(b.hi.z)});
    const float pad = scale * 4.8e-7f + 1e-30f;  // about 8 ulps
    return {b.lo - pad, b.hi + pad};
}

class Collapser {
public:
    Collapser(const BinaryBvh& binary, const std::vector<Face>& faces, WideBvh& wide)
        : binary_(binary), faces_(faces), wide_(wide) {}

    // A binary subtree of at most four blocks' worth of faces becomes one leaf (a run of
    // consecutive blocks) rather than a wide node over its binary leaves when the surface-area
    // heuristic says so: area * blocks <= area * kNodeCost + the sum over its binary leaves of
    // area * blocks, in units of one block test. A node test costs about three block tests in
    // bench/embree_compare (kernels/bvh_traverse.h; the nodes' memory counts, not only their
    // arithmetic): thin nodes at the tree's bottom had been most of its nodes. At this cost a
    // subtree of up to 12 faces (3 blocks) is always a leaf; the heuristic decides only for 13
    // to 16, where a leaf of 4 blocks must beat a node over tighter leaves.
    static constexpr std::uint32_t kMaxLeafFaces = RAD_MAX_LEAF_BLOCKS * RAD_LEAF_SIZE;
    static constexpr double kNodeCost = 3.0;

    // Returns the index of a wide node whose children start as the given binary nodes.
    std::uint32_t collapse(std::vector<std::int32_t> children) {
        // Open the largest inner child until eight children or only leaves remain.
        while (children.size() < RAD_BVH_WIDTH) {
            int widest = -1;
            float widestArea = -1.0f;
            for (std::size_t i = 0; i < children.size(); ++i) {
                const BinaryBvhNode& n = binary_.nodes[children[i]];
                if (n.isLeaf()) continue;
                const glm::vec3 e = n.box.extent();
                const float area = e.x * e.y + e.y * e.z + e.z * e.x;
                if (area > widestArea) widestArea = area, widest = static_cast<int>(i);
            }
            if (widest < 0) break;
            const BinaryBvhNode& opened = binary_.nodes[children[widest]];
            children[widest] = opened.left;
            children.push_back(opened.right);
        }
        const auto index = static_cast<std::uint32_t>(wide_.nodes.size());
        wide_.nodes.emplace_back();
        emptyNode(wide_.nodes[index]);
        for (std::size_t slot = 0; slot < children.size(); ++slot) {
            const BinaryBvhNode& child = binary_.nodes[children[slot]];
            const std::int32_t link = child.isLeaf() || leafIsCheaper(children[slot])
                                          ? addLeaf(children[slot])
                                          : static_cast<std::int32_t>(collapse({child.left, child.right}));
            BvhNode& node = wide_.nodes[index];  // collapse() may have grown the vector
            const Bounds box = padded(child.box);
            for (int axis = 0; axis < 3; ++axis) {
                node.lo[axis][slot] = box.lo[axis];
                node.hi[axis][slot] = box.hi[axis];
            }
            node.child[slot] = link;
        }
        return index;
    }

    // Lays the faces of the binary subtree under `node` into consecutive blocks, four to a block
    // in the subtree's order, and returns the child link to them (RAD_LEAF_LINK).
    std::int32_t addLeaf(std::int32_t node) {
        std::vector<std::uint32_t> faces;
        collectFaces(node, faces);
        const auto first = static_cast<std::uint32_t>(wide_.blocks.size());
        const auto count = static_cast<std::uint32_t>((faces.size() + RAD_LEAF_SIZE - 1) / RAD_LEAF_SIZE);
        if (first + count > RAD_MAX_LEAF_BLOCK)
            throw RuntimeFailure("the BVH needs more than " + std::to_string(RAD_MAX_LEAF_BLOCK) + " leaf blocks");
        for (std::size_t start = 0; start < faces.size(); start += RAD_LEAF_SIZE) {
            LeafBlock block{};
            const std::size_t used = std::min<std::size_t>(RAD_LEAF_SIZE, faces.size() - start);
            for (std::size_t lane = 0; lane < RAD_LEAF_SIZE; ++lane) {
                // Unused lanes repeat the block's first face: they can only report a hit that lane 0 reports too.
                const std::uint32_t f = faces[start + (lane < used ? lane : 0)];
                for (int v = 0; v < 3; ++v)
                    for (int axis = 0; axis < 3; ++axis) block.v[v][axis][lane] = faces_[f].p[v][axis];
                block.face[lane] = lane < used ? static_cast<rad_int>(f) : -1;
            }
            wide_.blocks.push_back(block);
        }
        return RAD_LEAF_LINK(first, count);
    }

private:
    static void emptyNode(BvhNode& node) {
        for (int axis = 0; axis < 3; ++axis)
            for (int slot = 0; slot < RAD_BVH_WIDTH; ++slot) {
                node.lo[axis][slot] = 1e30f;
                node.hi[axis][slot] = -1e30f;
            }
        for (int slot = 0; slot < RAD_BVH_WIDTH; ++slot) node.child[slot] = RAD_EMPTY_CHILD;
    }

    // In double, as binary_bvh.cpp: boxes near the float range would overflow in float.
    double halfAreaOf(std::int32_t node) const {
        const Bounds& box = binary_.nodes[node].box;
        const glm::dvec3 e = glm::dvec3(box.hi) - glm::dvec3(box.lo);
        return e.x * e.y + e.y * e.z + e.z * e.x;
    }

    static double blocksFor(std::uint32_t faces) { return double((faces + RAD_LEAF_SIZE - 1) / RAD_LEAF_SIZE); }

    // The sum over the binary leaves under `node` of area * blocks.
    double leavesCost(std::int32_t node) const {
        const BinaryBvhNode& n = binary_.nodes[node];
        if (n.isLeaf()) return halfAreaOf(node) * blocksFor(n.count);
        return leavesCost(n.left) + leavesCost(n.right);
    }

    bool leafIsCheaper(std::int32_t node) const {
        if (faceCount_[node] > kMaxLeafFaces) return false;
        const double area = halfAreaOf(node);
        return area * blocksFor(faceCount_[node]) <= area * kNodeCost + leavesCost(node);
    }

    void collectFaces(std::int32_t node, std::vector<std::uint32_t>& faces) const {
        const BinaryBvhNode& n = binary_.nodes[node];
        if (!n.isLeaf()) {
            collectFaces(n.left, faces);
            collectFaces(n.right, faces);
            return;
        }
        for (std::uint32_t i = n.first; i < n.first + n.count; ++i) faces.push_back(binary_.order[i]);
    }

    // Faces under each binary node.
    static std::vector<std::uint32_t> countFaces(const BinaryBvh& binary) {
        std::vector<std::uint32_t> count(binary.nodes.size(), 0);
        // Children come after their parents, so a reverse sweep sees children first.
        for (std::size_t i = binary.nodes.size(); i-- > 0;) {
            const BinaryBvhNode& n = binary.nodes[i];
            count[i] = n.isLeaf() ? n.count : count[n.left] + count[n.right];
        }
        return count;
    }

    const BinaryBvh& binary_;
    const std::vector<Face>& faces_;
    WideBvh& wide_;
    const std::vector<std::uint32_t> faceCount_ = countFaces(binary_);
};

// Stack entries a traversal below `node` can need: pushing k children, popping one, and what
// that child needs in turn.
std::uint32_t stackNeeded(const WideBvh& bvh, std::uint32_t node) {
    std::uint32_t k = 0, deepest = 0;
    for (int slot = 0; slot < RAD_BVH_WIDTH; ++slot) {
        const rad_int child = bvh.nodes[node].child[slot];
        if (child == RAD_EMPTY_CHILD) continue;
        ++k;
        if (child >= 0) deepest = std::max(deepest, stackNeeded(bvh, static_cast<std::uint32_t>(child)));
    }
    return std::max(k, k - 1 + deepest);
}

std::uint32_t depth(const BinaryBvh& bvh, std::int32_t node) {
    if (bvh.nodes[node].isLeaf()) return 1;
    return 1 + std::max(depth(bvh, bvh.nodes[node].left), depth(bvh, bvh.nodes[node].right));
}

}  // namespace

WideBvh buildWideBvh(const std::vector<Face>& faces) {
    if (faces.empty()) throw InputError("there is nothing to trace: the scene has no faces");
    std::vector<Bounds> boxes(faces.size());
    for (std::size_t f = 0; f < faces.size(); ++f)
        for (const glm::vec3& p : faces[f].p) boxes[f].extend(p);
    const BinaryBvh binary = buildBinaryBvh(boxes, RAD_LEAF_SIZE);

    WideBvh wide;
    wide.binaryDepth = depth(binary, 0);
    // The root is always an inner node; a scene of at most four faces gets one leaf child.
    const BinaryBvhNode& root = binary.nodes[0];
    Collapser(binary, faces, wide).collapse(root.isLeaf() ? std::vector<std::int32_t>{0}
                                                           : std::vector<std::int32_t>{root.left, root.right});
    wide.stackNeeded = stackNeeded(wide, 0);
    if (wide.stackNeeded > RAD_STACK_SIZE)
        throw RuntimeFailure("the BVH could need " + std::to_string(wide.stackNeeded) +
                             " traversal stack entries; the kernels hold " + std::to_string(RAD_STACK_SIZE));
    return wide;
}

}  // namespace rad
