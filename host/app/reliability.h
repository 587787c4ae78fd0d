#pragma once
// Where a result can be told to be unreliable from what the program already knows, with the
// remedy: warnings for stderr and report.json. Each check is cheap next to the solve it
// guards, and each names the figures it rests on, so a user can judge it.
//
//  - Receivers too small for the sampling (shoot matrices and surface view factors, hemicube):
//    the smallest receiver, facing its source from across the scene (the bounding box's
//    diagonal D), has the form factor F = A / (pi D^2). A shooter's rays resolve F down to
//    1 / rays; a hemicube's pixels down to the centre pixel's delta form factor 4 / (pi R^2).
//    Fewer than one sample per such receiver: it is missed or counted whole (aliasing). Surface
//    view factors (`viewfactors`, shooting) are read entry by entry, so there fewer than 100
//    rays (10 % noise) is already a warning, with the noise it implies.
//  - Near field with a point-sampled estimator (hemicube: each patch's centre; gather: three
//    points of each receiver): patches facing each other nearer than their own size, as at
//    corners and contacts, where the form factor varies across the patch.
//  - Too few ray hits (progressive shooting): from the solution, how many ray hits each
//    receiver's (element's) radiosity rests on; its relative noise is about 1 / sqrt(hits).

#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "app/commands.h"
#include "mesh/elements.h"
#include "mesh/mesh.h"
#include "prepared/prepared_scene.h"

namespace rad {

// Before the work. raysPerSource: the rays from each source of the shoot estimator (rays per
// patch for a matrix, per surface when `surfaceSources`); ignored by the other methods.
std::vector<std::string> samplingWarnings(const Mesh& mesh, const MethodArgs& method, std::uint64_t raysPerSource,
                                          bool surfaceSources);

// After a progressive shooting solve with `rays` for a shot of all the emitted power;
// `radiosity` is per element (the receivers).
std::vector<std::string> rayHitWarnings(const PreparedScene& scene, const ElementMesh& elements,
                                        const std::vector<glm::vec3>& radiosity, std::uint64_t rays);

// Prints each as "radiosity: warning: ..." on stderr and appends it to `report` when given.
void emitWarnings(const std::vector<std::string>& warnings, std::vector<std::string>* report = nullptr);

}  // namespace rad
