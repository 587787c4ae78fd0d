#pragma once
// Where a progressive shooting solve can be told to be unreliable after the work: from the
// noise the solver expects in each receiver's (element's) radiosity, from the ray hits its
// reflected light rests on (ProgressiveResult::receivers). The warning names the figures and the
// remedy.
//
// The figure is the noise of the values where they are seen: the RMS over the reflecting
// surfaces' area of each element's expected error, over their area-weighted mean radiosity, the
// measure bench/clusters checks against long solves. An image, a lightmap or a surface's heat
// balance reads an element in proportion to its area, and a dim one's noise in proportion to
// its light; a count of hits per element would be ruled by the smallest and darkest elements
// (a finely tessellated part's fillets, the insides of an assembly) that no output shows.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace rad {

// One receiver that reflects light, summed over the channels it reflects.
struct ReceiverNoise {
    double area = 0.0;        // m^2
    double radiosity = 0.0;   // W/m^2
    double noise = 0.0;       // W/m^2: the expected error of that radiosity (its standard deviation)
    bool hit = false;         // whether any shot's ray brought it light
};

// The RMS over area of the receivers' expected errors over their area-weighted mean radiosity;
// 0 where none has light.
double relativeNoise(const std::vector<ReceiverNoise>& receivers);

// Above this relative noise the solve warns: values that far apart are plainly speckled on a
// surface, and a heat flux that uncertain is no answer; where the light is even it is 100 hits
// per element.
constexpr double kNoiseToWarn = 0.1;

// After a progressive shooting solve with `rays` for a shot of all the power to shoot;
// `receivers` per element that reflects light, `patches` the patch count (more elements than
// patches: the patches were split, and the remedy is a coarser split).
std::vector<std::string> rayHitWarnings(const std::vector<ReceiverNoise>& receivers, std::size_t elements,
                                        std::size_t patches, std::uint64_t rays);

}  // namespace rad
