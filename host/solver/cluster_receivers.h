#pragma once
// Small patches receive in clusters (mesh/patch_clusters.h) where their own hits cannot tell
// their light apart. A patch far smaller than the patch size is hit by few of a solve's rays:
// its own estimate of the light the shots brought is a handful of hits (or none), its relative
// noise 1 / sqrt(hits). The light its cluster received rests on the hits of all its patches.
//
// For each cluster of more than one patch, the elements of its patches are pooled where their
// own hits agree with the cluster's light: each element's hits k are tested against what the
// cluster's hits per square metre predict for its area, k^ = A K / A_cluster, as a Poisson count:
// |k - k^| <= 3 sqrt(k^) + 1. The elements that agree share their summed power in proportion
// to area (so the power they received is kept, channel by channel); the others, where the light
// really changes across the cluster (a shadow's edge, a bright spot), keep their own. With few
// hits everywhere the cluster acts as one receiver of its size, which is what a patch of a large
// face is; with many, every element that differs from its neighbours by more than its noise
// keeps its own value, so the pooled result converges to the elements' own as rays grow.
//
// Only the light that shots brought is pooled: the direct light of emitters the solver does not
// shoot (solver/direct_light.h) has its own samples on every element.

#include <vector>

#include <glm/vec3.hpp>

#include "mesh/elements.h"
#include "mesh/patch_clusters.h"

namespace rad {

struct PooledReceivers {
    std::vector<glm::dvec3> power;  // per element: the shots' power it is given (pooled or its own)
    std::vector<double> hits;       // per element: about how many ray hits that value rests on
    std::size_t pooled = 0;         // elements whose value is their cluster's
};

// `shot`: per element, the power the shots delivered (any unit); `rayPower`: what one ray carries,
// summed over channels, in the same unit.
PooledReceivers poolReceivers(const ElementMesh& elements, const PatchClusters& clusters,
                              const std::vector<glm::dvec3>& shot, double rayPower);

}  // namespace rad
