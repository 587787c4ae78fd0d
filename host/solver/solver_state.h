#pragma once
// Everything a progressive solve needs to continue where it was: the per-patch state (as the
// device holds it, bit for bit), each shooter's place in its sample sequence, and the tallies.
// A solve resumed from a state saved after batch b takes exactly the steps the uninterrupted
// solve took after batch b, so it ends with bitwise the same result.

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace rad {

// How far a progressive solve has come: shots taken, rays cast, batches run. One record for the
// solve's result, its saved states and the report.
struct SolveTallies {
    std::uint64_t shots = 0, rays = 0, batches = 0;
};

struct SolverState {
    // Powers are in the solver's device units (watts times a power of two that puts the
    // strongest channel's emitted power in [1, 2)).
    // Per element: power that has arrived (rgb), and the element's own unshot power, summed
    // over channels (w): where its patch's next shot starts its rays.
    std::vector<std::array<float, 4>> incident;
    std::vector<std::array<float, 4>> unshot;    // per patch: power not yet shot
    // Per element, with mirrors or glass: the incident power that came by way of them (rgb;
    // w unused); empty without.
    std::vector<std::array<float, 4>> caustic;
    std::vector<std::uint64_t> samplesUsed;      // per patch: samples its shots have taken
    glm::dvec3 escaped{0.0};                      // power that left the scene
    glm::dvec3 absorbedByBacks{0.0};              // power that black backs absorbed
    glm::dvec3 shot{0.0};                         // power shot, signed (solver/amplification.h)
    SolveTallies tallies;
    double seconds = 0.0;                         // solving time spent to reach this state
};

}  // namespace rad
