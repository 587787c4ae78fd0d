#pragma once
// printf-style formatting into a std::string, for messages with figures (warnings, errors).

#include <cstdarg>
#include <cstdio>
#include <string>

namespace rad {

inline std::string format(const char* fmt, ...) __attribute__((format(printf, 1, 2)));
inline std::string format(const char* fmt, ...) {
    char text[1024];
    va_list args;
    va_start(args, fmt);
    std::vsnprintf(text, sizeof text, fmt, args);
    va_end(args);
    return text;
}

}  // namespace rad
