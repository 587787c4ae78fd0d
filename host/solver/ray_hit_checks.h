#pragma once
// Where a progressive shooting solve can be told to be unreliable after the work: from the
// solver's own count of the ray hits each receiver's (element's) reflected light rests on
// (ProgressiveResult::hits; its relative noise is about 1 / sqrt(hits)). The warning names the
// figures and the remedy.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace rad {

// After a progressive shooting solve with `rays` for a shot of all the power to shoot; `hits` is
// per element (the receivers; below 0 for those that reflect nothing), `patches` the patch count
// (more elements than patches: the patches were split, and the remedy is a coarser split).
std::vector<std::string> rayHitWarnings(const std::vector<double>& hits, std::size_t patches, std::uint64_t rays);

}  // namespace rad
