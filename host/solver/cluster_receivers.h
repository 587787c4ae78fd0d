#pragma once
// Small patches receive in clusters (mesh/patch_clusters.h) where their own hits cannot tell
// their light apart. A patch far smaller than the patch size is hit by few of a solve's rays:
// its own estimate of the light the shots brought is a handful of hits (or none), its relative
// noise 1 / sqrt(hits). The light its cluster received rests on the hits of all its patches.
//
// For each cluster of more than one patch, its elements' own hits k are first tested against
// what the cluster's hits per square metre predict for their area, k^ = A K / A_cluster, as a
// Poisson count: those with |k - k^| > 3 sqrt(k^) + 1, where the light plainly differs (a
// shadow's edge, a bright spot), keep their own value. The others are shrunk towards their pool's
// density by how much the light among them varies beyond their noise (empirical Bayes, as for
// Poisson rates with a common prior): with m the pool's prediction for an element and v the
// relative variance of the true densities, estimated from the counts as
// sum((k - m)^2 - m) / sum(m^2) (at least 0), an element keeps the share v m / (v m + 1) of its
// own value and takes the rest from the pool. Where the light is even, v is near 0 and the pool
// acts as one receiver of its size, which is what a patch of a large face is; where it varies,
// or as an element's hits grow, its own value takes over, so the result converges to the
// elements' own as rays grow. The pool's power is kept, channel by channel.
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
    std::vector<double> hits;       // per element: 1 / that value's relative mean squared error, in ray hits
    std::size_t pooled = 0;         // elements whose value is more their pool's than their own
};

// `shot`: per element, the power the shots delivered (any unit); `rayPower`: what one ray carries,
// summed over channels, in the same unit.
PooledReceivers poolReceivers(const ElementMesh& elements, const PatchClusters& clusters,
                              const std::vector<glm::dvec3>& shot, double rayPower);

}  // namespace rad
