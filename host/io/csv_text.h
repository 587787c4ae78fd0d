#pragma once
// Text of CSV fields: names quoted per RFC 4180 where they need it, numbers to a given number
// of significant digits ("nan" where there is none).

#include <string>

namespace rad {

std::string csvField(const std::string& text);
std::string csvNumber(double value, int digits);
// Text for a comment line (Matrix Market's `%` lines): line breaks become spaces.
std::string oneLine(std::string text);

}  // namespace rad
