#include "mesh/patch_clusters.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include <glm/geometric.hpp>

namespace rad {
namespace {

float longestEdge(const Patch& p) {
    return std::max({glm::length(p.p[1] - p.p[0]), glm::length(p.p[2] - p.p[1]), glm::length(p.p[0] - p.p[2])});
}

// Small: under half the patch size across, or under a sixteenth of its square in area (a sliver
// of CAD tessellation, however long). A patch of a face split in n x n is neither unless the face
// is thin: a right isosceles patch whose longest edge is half the patch size has that area.
bool small(const Patch& p, double patchSize) {
    return longestEdge(p) < 0.5 * patchSize || static_cast<double>(p.area) < patchSize * patchSize / 16.0;
}

// Which of the six axis directions the normal is nearest: patches of one cluster face within
// 109 degrees of each other at most, so a cluster never folds over a thin part's two sides.
int facingBucket(const glm::vec3& n) {
    const glm::vec3 a = glm::abs(n);
    const int axis = a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2);
    return 2 * axis + (n[axis] < 0.0f ? 1 : 0);
}

}  // namespace

PatchClusters PatchClusters::identity(std::size_t patchCount) {
    PatchClusters c;
    c.start_.resize(patchCount + 1);
    c.members_.resize(patchCount);
    for (std::size_t p = 0; p < patchCount; ++p) {
        c.start_[p] = static_cast<std::uint32_t>(p);
        c.members_[p] = static_cast<std::uint32_t>(p);
    }
    c.start_[patchCount] = static_cast<std::uint32_t>(patchCount);
    c.largest_ = patchCount > 0 ? 1u : 0u;
    return c;
}

PatchClusters PatchClusters::of(const Mesh& mesh) {
    const std::size_t patchCount = mesh.patches.size();
    const double cell = mesh.patchSize / std::sqrt(2.0);  // a cell's diagonal is one patch size
    if (!(cell > 0.0)) return identity(patchCount);
    // Patches in the order of their clusters' first patch: a small patch joins the open cluster
    // of its key, or opens one; a full cluster is closed and the next of its key opens anew.
    using Key = std::tuple<std::uint32_t, int, int, std::int64_t, std::int64_t, std::int64_t>;
    std::map<Key, std::uint32_t> open;
    std::vector<std::vector<std::uint32_t>> clusters;
    clusters.reserve(patchCount);
    for (std::size_t p = 0; p < patchCount; ++p) {
        const Patch& patch = mesh.patches[p];
        if (!small(patch, mesh.patchSize)) {
            clusters.push_back({static_cast<std::uint32_t>(p)});
            continue;
        }
        const glm::dvec3 centre = (glm::dvec3(patch.p[0]) + glm::dvec3(patch.p[1]) + glm::dvec3(patch.p[2])) / 3.0;
        const Key key{patch.surface, patch.material, facingBucket(patch.normal),
                      static_cast<std::int64_t>(std::floor(centre.x / cell)),
                      static_cast<std::int64_t>(std::floor(centre.y / cell)),
                      static_cast<std::int64_t>(std::floor(centre.z / cell))};
        const auto found = open.find(key);
        if (found != open.end() && clusters[found->second].size() < kMaxMembers) {
            clusters[found->second].push_back(static_cast<std::uint32_t>(p));
        } else {
            open[key] = static_cast<std::uint32_t>(clusters.size());
            clusters.push_back({static_cast<std::uint32_t>(p)});
        }
    }
    PatchClusters c;
    c.start_.reserve(clusters.size() + 1);
    c.members_.reserve(patchCount);
    for (const std::vector<std::uint32_t>& members : clusters) {
        c.members_.insert(c.members_.end(), members.begin(), members.end());
        c.start_.push_back(static_cast<std::uint32_t>(c.members_.size()));
        c.largest_ = std::max(c.largest_, static_cast<std::uint32_t>(members.size()));
    }
    return c;
}

}  // namespace rad
