// Writes EXT_meshopt_compression files for tests/cli/meshopt.sh from a glTF scene whose one
// buffer is a data URI (the generated scenes are), with libmeshoptimizer's own encoders:
//   exact.gltf       every buffer view compressed, attributes without a filter and indices as
//                    index sequences (both exact), the placeholder buffer without a URI
//   triangles.glb    the same in a .glb, indices by the triangle codec (it may rotate each
//                    triangle's corners, keeping its winding), the placeholder buffer tagged
//                    `fallback`
//   lossy.gltf       positions through the exponential filter with 12-bit mantissas
//   bad-*.gltf       one broken property each (tests/cli/meshopt.sh lists the messages)
// Usage: meshopt_fixtures SCENE.gltf DIR

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <cstdio>
#include <fstream>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <meshoptimizer.h>
#include <nlohmann/json.hpp>

namespace {

using Json = nlohmann::json;
using Bytes = std::vector<unsigned char>;

const char* kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

Bytes fromBase64(const std::string& text) {
    Bytes out;
    std::uint32_t bits = 0;
    int count = 0;
    for (char c : text) {
        const char* at = std::strchr(kAlphabet, c);
        if (c == '=' || !at || !c) continue;
        bits = (bits << 6) | static_cast<std::uint32_t>(at - kAlphabet);
        if ((count += 6) >= 8) out.push_back(static_cast<unsigned char>((bits >> (count -= 8)) & 0xFFu));
    }
    return out;
}

std::string toBase64(const Bytes& bytes) {
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        const std::uint32_t a = bytes[i], b = i + 1 < bytes.size() ? bytes[i + 1] : 0,
                            c = i + 2 < bytes.size() ? bytes[i + 2] : 0;
        const std::uint32_t v = (a << 16) | (b << 8) | c;
        out += kAlphabet[(v >> 18) & 63];
        out += kAlphabet[(v >> 12) & 63];
        out += i + 1 < bytes.size() ? kAlphabet[(v >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? kAlphabet[v & 63] : '=';
    }
    return out;
}

std::size_t componentSize(int type) { return type == 5126 || type == 5125 ? 4 : type == 5123 || type == 5122 ? 2 : 1; }
std::size_t components(const std::string& type) {
    return type == "SCALAR" ? 1 : type == "VEC2" ? 2 : type == "VEC3" ? 3 : type == "VEC4" ? 4 : 16;
}

struct Options {
    bool triangles = false;    // indices by the triangle codec instead of as sequences
    int positionBits = 0;      // > 0: positions through the exponential filter
};

// The scene with every buffer view compressed into buffer 0 and a placeholder buffer 1; returns
// the JSON and the compressed bytes.
std::pair<Json, Bytes> compress(Json doc, const Options& options) {
    const Bytes source = fromBase64(doc["buffers"][0]["uri"].get<std::string>().substr(
        doc["buffers"][0]["uri"].get<std::string>().find(',') + 1));
    std::vector<std::size_t> stride(doc["bufferViews"].size(), 0);
    std::vector<bool> isIndex(doc["bufferViews"].size(), false), isPosition(doc["bufferViews"].size(), false);
    for (const auto& mesh : doc["meshes"])
        for (const auto& primitive : mesh["primitives"]) {
            if (primitive.contains("indices"))
                isIndex[doc["accessors"][primitive["indices"].get<std::size_t>()]["bufferView"].get<std::size_t>()] = true;
            const std::size_t position = primitive["attributes"]["POSITION"].get<std::size_t>();
            isPosition[doc["accessors"][position]["bufferView"].get<std::size_t>()] = true;
        }
    for (const auto& accessor : doc["accessors"]) {
        const auto view = accessor["bufferView"].get<std::size_t>();
        stride[view] = componentSize(accessor["componentType"].get<int>()) * components(accessor["type"].get<std::string>());
    }
    Bytes packed;
    for (std::size_t v = 0; v < doc["bufferViews"].size(); ++v) {
        Json& view = doc["bufferViews"][v];
        const std::size_t offset = view.value("byteOffset", 0), length = view["byteLength"].get<std::size_t>();
        const std::size_t size = view.contains("byteStride") ? view["byteStride"].get<std::size_t>() : stride[v];
        const std::size_t count = length / size;
        Bytes encoded;
        std::string mode = "ATTRIBUTES", filter = "NONE";
        if (isIndex[v]) {
            std::vector<std::uint32_t> indices(count);
            for (std::size_t i = 0; i < count; ++i)
                indices[i] = size == 2 ? source[offset + 2 * i] | (source[offset + 2 * i + 1] << 8)
                                       : source[offset + 4 * i] | (source[offset + 4 * i + 1] << 8) |
                                             (source[offset + 4 * i + 2] << 16) |
                                             (std::uint32_t(source[offset + 4 * i + 3]) << 24);
            std::uint32_t vertices = 0;
            for (std::uint32_t i : indices) vertices = std::max(vertices, i + 1);
            if (options.triangles) {
                mode = "TRIANGLES";
                encoded.resize(meshopt_encodeIndexBufferBound(count, vertices));
                encoded.resize(meshopt_encodeIndexBuffer(encoded.data(), encoded.size(), indices.data(), count));
            } else {
                mode = "INDICES";
                encoded.resize(meshopt_encodeIndexSequenceBound(count, vertices));
                encoded.resize(meshopt_encodeIndexSequence(encoded.data(), encoded.size(), indices.data(), count));
            }
        } else {
            Bytes elements(source.begin() + static_cast<std::ptrdiff_t>(offset),
                           source.begin() + static_cast<std::ptrdiff_t>(offset + length));
            std::size_t encodedStride = size;
            if (options.positionBits > 0 && isPosition[v] && size == 12) {
                std::vector<float> values(count * 3);
                std::memcpy(values.data(), elements.data(), elements.size());
                meshopt_encodeFilterExp(elements.data(), count, 12, options.positionBits, values.data());
                filter = "EXPONENTIAL";
            }
            encoded.resize(meshopt_encodeVertexBufferBound(count, encodedStride));
            encoded.resize(meshopt_encodeVertexBuffer(encoded.data(), encoded.size(), elements.data(), count, encodedStride));
        }
        if (encoded.empty()) throw std::runtime_error("meshoptimizer cannot encode buffer view " + std::to_string(v));
        while (packed.size() % 4) packed.push_back(0);
        view["extensions"][std::string("EXT_meshopt_compression")] = {
            {"buffer", 0},        {"byteOffset", packed.size()}, {"byteLength", encoded.size()},
            {"byteStride", size}, {"count", count},              {"mode", mode}};
        if (filter != "NONE") view["extensions"]["EXT_meshopt_compression"]["filter"] = filter;
        view["buffer"] = 1;
        packed.insert(packed.end(), encoded.begin(), encoded.end());
    }
    doc["buffers"] = Json::array({Json{{"byteLength", packed.size()}}, Json{{"byteLength", source.size()}}});
    doc["extensionsUsed"].push_back("EXT_meshopt_compression");
    doc["extensionsRequired"] = Json::array({"EXT_meshopt_compression"});
    return {doc, packed};
}

std::string gltf(Json doc, const Bytes& packed) {
    doc["buffers"][0]["uri"] = "data:application/octet-stream;base64," + toBase64(packed);
    return doc.dump(1);
}

std::string glb(Json doc, Bytes bin) {
    doc["buffers"][1]["extensions"]["EXT_meshopt_compression"] = {{"fallback", true}};
    std::string json = doc.dump();
    json.append((4 - json.size() % 4) % 4, ' ');
    while (bin.size() % 4) bin.push_back(0);
    std::string out;
    auto u32 = [&out](std::uint32_t v) { out.append(reinterpret_cast<const char*>(&v), 4); };
    u32(0x46546C67);
    u32(2);
    u32(static_cast<std::uint32_t>(12 + 8 + json.size() + 8 + bin.size()));
    u32(static_cast<std::uint32_t>(json.size()));
    u32(0x4E4F534A);
    out += json;
    u32(static_cast<std::uint32_t>(bin.size()));
    u32(0x004E4942);
    out.append(bin.begin(), bin.end());
    return out;
}

Json& ext(Json& view) { return view["extensions"]["EXT_meshopt_compression"]; }

// The exact file with buffer view 0 or its extension changed.
std::string broken(const Json& doc, const Bytes& packed, const std::function<void(Json&)>& change) {
    Json copy = doc;
    change(copy["bufferViews"][0]);
    return gltf(copy, packed);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: meshopt_fixtures SCENE.gltf DIR\n");
        return 2;
    }
    try {
        std::ifstream in(argv[1]);
        std::stringstream text;
        text << in.rdbuf();
        const Json scene = Json::parse(text.str());
        const std::string dir = argv[2];
        const auto [exact, exactBytes] = compress(scene, {});
        const auto [triangles, triangleBytes] = compress(scene, {true, 0});
        const auto [lossy, lossyBytes] = compress(scene, {false, 12});
        const std::pair<std::string, std::string> files[] = {
            {"exact.gltf", gltf(exact, exactBytes)},
            {"triangles.glb", glb(triangles, triangleBytes)},
            {"lossy.gltf", gltf(lossy, lossyBytes)},
            {"bad-cut.gltf", broken(exact, exactBytes, [](Json& v) { ext(v)["byteLength"] = ext(v)["byteLength"].get<int>() / 2; })},
            {"bad-count.gltf", broken(exact, exactBytes, [](Json& v) { ext(v)["count"] = ext(v)["count"].get<int>() + 1; })},
            {"bad-mode.gltf", broken(exact, exactBytes, [](Json& v) { ext(v)["mode"] = "TRIANGLE_STRIP"; })},
            {"bad-filter.gltf", broken(exact, exactBytes, [](Json& v) { ext(v)["filter"] = "QUATERNION"; })},
            {"bad-offset.gltf", broken(exact, exactBytes, [](Json& v) { ext(v)["byteOffset"] = 1 << 20; })},
            {"bad-huge.gltf", broken(exact, exactBytes, [](Json& v) {
                 ext(v)["count"] = 100'000'000;  // 1.2 GB from a few dozen bytes
                 v["byteLength"] = 1'200'000'000;
             })},
        };
        for (const auto& [name, bytes] : files) {
            std::ofstream out(dir + "/" + name, std::ios::binary);
            out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
            if (!out) throw std::runtime_error("cannot write " + dir + "/" + name);
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "meshopt_fixtures: %s\n", e.what());
        return 1;
    }
    return 0;
}
