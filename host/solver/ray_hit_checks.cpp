#include "solver/ray_hit_checks.h"

#include <algorithm>
#include <cmath>

#include "util/format.h"

namespace rad {

std::vector<std::string> rayHitWarnings(const std::vector<double>& hits, std::size_t patches, std::uint64_t rays) {
    std::vector<double> reflecting;
    std::size_t none = 0;
    for (const double k : hits) {
        if (k < 0.0) continue;  // reflects nothing: its hits say nothing
        reflecting.push_back(k);
        if (!(k > 0.0)) ++none;
    }
    if (reflecting.empty() || rays == 0) return {};
    std::nth_element(reflecting.begin(), reflecting.begin() + reflecting.size() / 2, reflecting.end());
    const double median = reflecting[reflecting.size() / 2];
    // Fewer than 25 hits for the median receiver is 20 % noise, and many get none. (The tail is
    // no guide: a receiver that only weak shots reach looks sparse even when it is not, and some
    // are out of every light's reach.)
    if (median >= 25.0) return {};
    const bool split = hits.size() > patches;
    const char* unit = split ? "element" : "patch";
    const char* units = split ? "elements" : "patches";
    const double needed = std::ceil(static_cast<double>(rays) * 100.0 / std::max(median, 0.1));
    const std::string effect = median > 0.0 ? format(
                                                  "%s values carry about %.0f %% noise and small receivers may get "
                                                  "no hit at all",
                                                  unit, 100.0 / std::sqrt(median))
                                            : format("most %s got no light at all", units);
    return {
        format("shoot: the median %s's radiosity rests on about %.3g ray hits (%zu of %zu reflecting %s got "
               "none), so %s; use --rays %.3g or more (now %llu) for about 100 hits per %s, or a larger %s",
               unit, median, none, reflecting.size(), units, effect.c_str(), needed,
               static_cast<unsigned long long>(rays), unit, split ? "--element-size (or fewer refinements)" : "--patch-size")};
}

}  // namespace rad
