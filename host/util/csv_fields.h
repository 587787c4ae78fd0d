#pragma once
// Reading the CSV files users write by hand (properties files): one line's fields, and a field
// as a number, with the caller's way of failing (which names the file and the line).

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace rad {

// The fields of one CSV line: comma-separated, double quotes around fields that hold commas
// or quotes ("" inside for a quote), surrounding spaces trimmed.
std::vector<std::string> csvFields(const std::string& line);

// A finite number, or nothing for an empty field; calls `fail` (which throws) for text that is
// not one, naming it as `what`.
std::optional<double> csvNumber(const std::string& field, const std::function<void(const std::string&)>& fail,
                                const char* what);

}  // namespace rad
