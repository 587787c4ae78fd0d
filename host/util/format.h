#pragma once
// Formatting for messages with figures (warnings, errors): printf into a std::string, and
// sizes in bytes.

#include <cstdarg>
#include <cstdint>
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

// A size in bytes for people: "512 KiB" below a mebibyte, "37 MiB" above (rounded up).
inline std::string byteSize(std::uint64_t bytes) {
    if (bytes < (1u << 20)) return std::to_string((bytes + 1023) >> 10) + " KiB";
    return std::to_string((bytes + (1u << 20) - 1) >> 20) + " MiB";
}

}  // namespace rad
