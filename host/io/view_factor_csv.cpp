#include "io/view_factor_csv.h"

#include <cstdio>
#include <string>

namespace rad {
namespace {

std::string csvField(const std::string& text) {
    if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
    std::string quoted = "\"";
    for (char c : text) {
        if (c == '"') quoted += '"';
        quoted += c;
    }
    return quoted + '"';
}

std::string number(double value, int digits) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*g", digits, value);
    return buffer;
}

}  // namespace

void writeViewFactorCsv(std::ostream& out, const SurfaceViewFactors& factors) {
    out << "from,to,F,stderr\n";
    for (std::size_t i = 0; i < factors.size(); ++i)
        for (const auto& [j, hits] : factors.rows[i])
            out << csvField(factors.names[i]) << ',' << csvField(factors.names[j]) << ','
                << number(factors.factor(i, j), 9) << ',' << number(factors.standardError(i, j), 3) << '\n';
}

}  // namespace rad
