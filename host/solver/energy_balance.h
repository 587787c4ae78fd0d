#pragma once
// Where the emitted power went, per channel (W). Emitted = absorbed + escaped + unshot, to
// floating-point rounding: progressive refinement moves power, it never makes or loses any.

#include <glm/vec3.hpp>

namespace rad {

struct EnergyBalance {
    glm::dvec3 emitted{0.0};
    glm::dvec3 absorbed{0.0};         // by surfaces, (1 - rho) of what reached them, and black backs
    glm::dvec3 absorbedByBacks{0.0};  // the part of `absorbed` that black backs took
    glm::dvec3 escaped{0.0};          // left an open scene
    glm::dvec3 unshot{0.0};           // reflected but not yet shot when the solve stopped

    // |emitted - absorbed - escaped - unshot| / emitted, the largest over emitting channels.
    double relativeResidual() const;
};

}  // namespace rad
