#pragma once
// Clusters of small patches that shoot as one (Smits, Arvo and Greenberg 1994 call such groups
// clusters): where a scene's own triangles are smaller than the patch size, as in tessellated
// content, each triangle is a patch of its own and would be shot on its own, with at least
// --min-rays rays however little light it holds. A cluster gathers the small patches of one side
// of one surface, of one material, facing about the same way, in one cell of a grid as wide as
// a patch, so that together they are about the size of one patch of a large face; the
// progressive solver chooses, and gives rays to, clusters (solver/progressive_solver.h). Small
// means under half the patch size across, or under a sixteenth of its square in area (a sliver).
//
// A cluster's shot is its members' own shots, made at once: each member casts rays from itself,
// in proportion to its own power to shoot, carrying its own colour; so clustering changes when a
// patch shoots and how few rays it may cast, never what a ray carries or where it starts. Other
// patches are clusters of one, so a scene of large faces clusters as the identity and solves bit
// for bit as it would without.

#include <cstdint>
#include <vector>

#include "mesh/mesh.h"

namespace rad {

class PatchClusters {
public:
    // Every patch a cluster of its own.
    static PatchClusters identity(std::size_t patchCount);
    // The clusters of `mesh` (see above); at most kMaxMembers patches each.
    static PatchClusters of(const Mesh& mesh);

    static constexpr std::uint32_t kMaxMembers = 256;

    std::size_t count() const { return start_.size() - 1; }
    // Cluster c's patches are members()[start()[c] .. start()[c + 1]), in increasing order;
    // clusters are ordered by their first patch.
    const std::vector<std::uint32_t>& start() const { return start_; }
    const std::vector<std::uint32_t>& members() const { return members_; }
    std::uint32_t size(std::size_t c) const { return start_[c + 1] - start_[c]; }
    std::uint32_t largest() const { return largest_; }
    bool isIdentity() const { return count() == members_.size(); }

private:
    std::vector<std::uint32_t> start_{0}, members_;
    std::uint32_t largest_ = 0;
};

}  // namespace rad
