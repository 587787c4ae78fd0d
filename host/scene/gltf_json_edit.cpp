#include "scene/gltf_json_edit.h"

#include <cstdint>

#include <nlohmann/json.hpp>

namespace rad {

std::string editGltfJson(const std::string& bytes, bool binary, const std::function<bool(nlohmann::json&)>& edit) {
    auto u32 = [&bytes](std::size_t at) {
        std::uint32_t v = 0;
        for (int k = 3; k >= 0; --k) v = (v << 8) | static_cast<unsigned char>(bytes[at + static_cast<std::size_t>(k)]);
        return v;
    };
    std::size_t jsonLength = bytes.size();
    if (binary) {
        if (bytes.size() < 20 || u32(16) != 0x4E4F534Au || u32(12) > bytes.size() - 20) return bytes;
        jsonLength = u32(12);
    }
    const std::size_t start = binary ? 20 : 0;
    nlohmann::json doc = nlohmann::json::parse(bytes.begin() + static_cast<std::ptrdiff_t>(start),
                                               bytes.begin() + static_cast<std::ptrdiff_t>(start + jsonLength), nullptr,
                                               false);
    if (doc.is_discarded() || !doc.is_object() || !edit(doc)) return bytes;
    std::string json = doc.dump();
    if (!binary) return json;
    json.append((4 - json.size() % 4) % 4, ' ');
    const std::string rest = bytes.substr(20 + jsonLength);  // the BIN chunk, if any
    std::string out = bytes.substr(0, 8);                    // magic and version
    auto put = [&out](std::uint32_t v) {
        for (int k = 0; k < 4; ++k) out.push_back(static_cast<char>((v >> (8 * k)) & 0xFFu));
    };
    put(static_cast<std::uint32_t>(20 + json.size() + rest.size()));
    put(static_cast<std::uint32_t>(json.size()));
    put(0x4E4F534Au);
    return out + json + rest;
}

}  // namespace rad
