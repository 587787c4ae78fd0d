#pragma once
// FNV-1a, 64 bits: a fingerprint of bytes (checksums and identities, not security).

#include <cstddef>
#include <cstdint>
#include <string>

namespace rad {

class Fnv1a {
public:
    Fnv1a& add(const void* data, std::size_t size) {
        const auto* p = static_cast<const unsigned char*>(data);
        for (std::size_t i = 0; i < size; ++i) hash_ = (hash_ ^ p[i]) * 0x100000001b3ull;
        return *this;
    }
    template <typename T>
    Fnv1a& add(const T& value) {
        return add(&value, sizeof value);
    }
    Fnv1a& add(const std::string& text) { return add(text.data(), text.size()); }
    std::uint64_t value() const { return hash_; }

private:
    std::uint64_t hash_ = 0xcbf29ce484222325ull;
};

}  // namespace rad
