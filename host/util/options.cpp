#include "util/options.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <vector>

namespace rad {

double OptionValues::number(const OptionSpec& spec) const {
    const auto found = numbers_.find(spec.name);
    if (found != numbers_.end()) return found->second;
    if (spec.kind == OptionKind::Size && !spec.defaultText.empty()) {
        double bytes = 0.0;
        if (parseSize(spec.defaultText, bytes)) return bytes;
    }
    return spec.defaultValue;
}

std::string OptionValues::text(const OptionSpec& spec) const {
    const auto found = texts_.find(spec.name);
    return found != texts_.end() ? found->second : spec.defaultText;
}

bool parseSize(const std::string& text, double& bytes) {
    std::size_t used = 0;
    double number = 0.0;
    try {
        number = std::stod(text, &used);
    } catch (const std::exception&) {
        return false;
    }
    const std::string suffix = text.substr(used);
    const double scale = suffix.empty()                   ? 1.0
                         : suffix == "K" || suffix == "k" ? 1024.0
                         : suffix == "M" || suffix == "m" ? 1048576.0
                         : suffix == "G" || suffix == "g" ? 1073741824.0
                         : suffix == "T" || suffix == "t" ? 1099511627776.0
                                                          : -1.0;
    if (scale < 0 || !(number > 0) || number * scale > 1.8e19) return false;
    bytes = number * scale;
    return true;
}

bool parseColour(const std::string& text, std::array<double, 3>& colour) {
    std::vector<double> values;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t end = std::min(text.find(',', start), text.size());
        const std::string part = text.substr(start, end - start);
        char* stop = nullptr;
        const double v = std::strtod(part.c_str(), &stop);
        if (part.empty() || stop != part.c_str() + part.size() || !std::isfinite(v) || v < 0.0 || v > 1e30)
            return false;
        values.push_back(v);
        start = end + 1;
    }
    if (values.size() == 1) values.assign(3, values[0]);
    if (values.size() != 3) return false;
    colour = {values[0], values[1], values[2]};
    return true;
}

}  // namespace rad
