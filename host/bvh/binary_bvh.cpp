#include "bvh/binary_bvh.h"

#include <algorithm>
#include <array>

#include <glm/common.hpp>

namespace rad {
namespace {

constexpr int kBins = 32;
// Beyond this depth splits fall back to the median, which bounds the depth the kernels'
// fixed traversal stack has to hold whatever the geometry.
constexpr int kMaxSahDepth = 48;

// In double: boxes of float coordinates near the float range would overflow in float.
double halfArea(const Bounds& b) {
    if (b.empty()) return 0.0;
    const glm::dvec3 e = glm::dvec3(b.hi) - glm::dvec3(b.lo);
    return e.x * e.y + e.y * e.z + e.z * e.x;
}

Bounds merge(Bounds a, const Bounds& b) {
    if (b.empty()) return a;
    a.extend(b.lo);
    a.extend(b.hi);
    return a;
}

glm::vec3 centroid(const Bounds& b) { return 0.5f * b.lo + 0.5f * b.hi; }  // no overflow near the float range

struct Split {
    int axis = -1;
    int firstRightBin = 0;  // centroids in this bin and above go right
    double cost = 0.0;
};

// The bin of centroid coordinate c in [lo, hi] (hi > lo), computed in double so that no
// float-to-int conversion can overflow.
int binOf(float c, float lo, float hi) {
    const double t = (static_cast<double>(c) - lo) / (static_cast<double>(hi) - lo) * kBins;
    return t >= kBins - 1 ? kBins - 1 : (t > 0.0 ? static_cast<int>(t) : 0);
}

// The best binned SAH split of order[first, first + count) over the three axes.
Split bestSplit(const std::vector<Bounds>& boxes, const std::vector<std::uint32_t>& order, std::uint32_t first,
                std::uint32_t count) {
    Bounds centroids;
    for (std::uint32_t i = first; i < first + count; ++i) centroids.extend(centroid(boxes[order[i]]));
    Split best;
    best.cost = std::numeric_limits<double>::max();
    for (int axis = 0; axis < 3; ++axis) {
        const float lo = centroids.lo[axis], hi = centroids.hi[axis];
        if (!(hi > lo)) continue;
        std::array<Bounds, kBins> binBox;
        std::array<std::uint32_t, kBins> binCount{};
        for (std::uint32_t i = first; i < first + count; ++i) {
            const Bounds& b = boxes[order[i]];
            const int bin = binOf(centroid(b)[axis], lo, hi);
            binBox[bin] = merge(binBox[bin], b);
            ++binCount[bin];
        }
        // Sweep from the right, then from the left, to cost every plane between bins.
        std::array<double, kBins> rightCost{};
        Bounds acc;
        std::uint32_t n = 0;
        for (int k = kBins - 1; k > 0; --k) {
            acc = merge(acc, binBox[k]);
            n += binCount[k];
            rightCost[k] = halfArea(acc) * n;
        }
        acc = Bounds();
        n = 0;
        for (int k = 0; k < kBins - 1; ++k) {
            acc = merge(acc, binBox[k]);
            n += binCount[k];
            if (n == 0 || n == count) continue;
            const double cost = halfArea(acc) * n + rightCost[k + 1];
            if (cost < best.cost) {
                // The plane between bins k and k + 1; partitioning uses the same binOf test.
                best = {axis, k + 1, cost};
            }
        }
    }
    return best;
}

}  // namespace

BinaryBvh buildBinaryBvh(const std::vector<Bounds>& boxes, std::uint32_t maxLeafSize) {
    BinaryBvh bvh;
    bvh.order.resize(boxes.size());
    for (std::uint32_t i = 0; i < bvh.order.size(); ++i) bvh.order[i] = i;
    bvh.nodes.reserve(2 * boxes.size() / std::max(1u, maxLeafSize) + 1);

    struct Task {
        std::uint32_t node, first, count;
        int depth;
    };
    bvh.nodes.push_back({});
    std::vector<Task> tasks{{0, 0, static_cast<std::uint32_t>(boxes.size()), 0}};
    while (!tasks.empty()) {
        const Task task = tasks.back();
        tasks.pop_back();
        Bounds box;
        for (std::uint32_t i = task.first; i < task.first + task.count; ++i) box = merge(box, boxes[bvh.order[i]]);
        bvh.nodes[task.node].box = box;
        if (task.count <= maxLeafSize) {
            bvh.nodes[task.node].first = task.first;
            bvh.nodes[task.node].count = task.count;
            continue;
        }
        auto begin = bvh.order.begin() + task.first;
        auto end = begin + task.count;
        std::uint32_t leftCount = 0;
        const Split split = task.depth < kMaxSahDepth ? bestSplit(boxes, bvh.order, task.first, task.count) : Split{};
        if (split.axis >= 0) {
            Bounds centroids;
            for (auto it = begin; it != end; ++it) centroids.extend(centroid(boxes[*it]));
            const float lo = centroids.lo[split.axis], hi = centroids.hi[split.axis];
            auto middle = std::partition(begin, end, [&](std::uint32_t p) {
                return binOf(centroid(boxes[p])[split.axis], lo, hi) < split.firstRightBin;
            });
            leftCount = static_cast<std::uint32_t>(middle - begin);
        }
        if (leftCount == 0 || leftCount == task.count) {
            // All centroids coincide (or the depth cap was hit): split at the median of the
            // widest axis, which always makes progress.
            const glm::dvec3 e = glm::dvec3(box.hi) - glm::dvec3(box.lo);
            const int axis = e.x >= e.y && e.x >= e.z ? 0 : (e.y >= e.z ? 1 : 2);
            leftCount = task.count / 2;
            std::nth_element(begin, begin + leftCount, end, [&](std::uint32_t a, std::uint32_t b) {
                const float ca = centroid(boxes[a])[axis], cb = centroid(boxes[b])[axis];
                return ca < cb || (ca == cb && a < b);
            });
        }
        const auto left = static_cast<std::uint32_t>(bvh.nodes.size());
        bvh.nodes.push_back({});
        bvh.nodes.push_back({});
        bvh.nodes[task.node].left = static_cast<std::int32_t>(left);
        bvh.nodes[task.node].right = static_cast<std::int32_t>(left + 1);
        tasks.push_back({left + 1, task.first + leftCount, task.count - leftCount, task.depth + 1});
        tasks.push_back({left, task.first, leftCount, task.depth + 1});
    }
    return bvh;
}

}  // namespace rad
