#pragma once
// Where a form-factor estimate can be told to be unreliable before the work, from the mesh and
// the sampling alone, with the remedy. Each check is cheap next to the work it guards, and
// each names the figures it rests on, so a user can judge it. The estimators' registry entries
// (estimator.h) call them.

#include <cstdint>
#include <string>
#include <vector>

#include "mesh/mesh.h"

namespace rad {

// Receivers too small for the sampling: the smallest receiver, facing its source from across
// the scene (the bounding box's diagonal D), has the form factor F = A / (pi D^2). A shooter's
// rays resolve F down to 1 / rays; a hemicube's pixels down to the centre pixel's delta form
// factor 4 / (pi R^2). Fewer than one sample per such receiver: it is missed or counted whole
// (aliasing). Surface view factors (`viewfactors`, shooting from whole surfaces:
// `surfaceSources`) are read entry by entry, so there fewer than 100 rays (10 % noise) is
// already a warning, with the noise it implies. `method` is "shoot" (raysPerSource rays from
// each source) or "hemicube" (hemicubeResolution pixels along the top face).
std::vector<std::string> smallReceivers(const Mesh& mesh, const std::string& method, std::uint32_t hemicubeResolution,
                                        std::uint64_t raysPerSource, bool surfaceSources);

// Near field with a point-sampled estimator (hemicube: each patch's centre; gather: three
// points of each receiver): patches facing each other nearer than their own size, as at
// corners and contacts, where the form factor varies across the patch.
std::vector<std::string> nearField(const Mesh& mesh, const std::string& method);

}  // namespace rad
