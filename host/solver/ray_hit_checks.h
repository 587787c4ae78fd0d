#pragma once
// Where a progressive shooting solve can be told to be unreliable after the work: from the
// solution, about how many ray hits each receiver's (element's) radiosity rests on; its
// relative noise is about 1 / sqrt(hits). The warning names the figures and the remedy.

#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "mesh/elements.h"
#include "prepared/prepared_scene.h"

namespace rad {

// After a progressive shooting solve with `rays` for a shot of all the emitted power, whose rays
// carried up to rayPowerScale times emitted / rays (solver/amplification.h); `radiosity` is per
// element (the receivers).
std::vector<std::string> rayHitWarnings(const PreparedScene& scene, const ElementMesh& elements,
                                        const std::vector<glm::vec3>& radiosity, std::uint64_t rays,
                                        double rayPowerScale = 1.0);

}  // namespace rad
