#include "scene/gltf_meshopt.h"

#include <cmath>
#include <cstdint>
#include <set>
#include <vector>

#include <meshoptimizer.h>
#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include "scene/gltf_json_edit.h"
#include "util/error.h"

namespace rad {
namespace {

constexpr const char* kExtension = "EXT_meshopt_compression";

// The codecs cannot expand a compressed byte into more than 64: an attribute block spends at
// least one header byte per 4 groups of 16 elements for each byte of an element, a triangle one
// code byte and an index one byte. A view that claims more cannot decode, so it is refused before
// its memory is allocated.
constexpr double kMostBytesPerCompressedByte = 64.0;
constexpr double kLargestView = 2147483648.0;  // 2 GiB

bool compressed(const nlohmann::json& view) {
    return view.is_object() && view.contains("extensions") && view["extensions"].is_object() &&
           view["extensions"].contains(kExtension);
}

// A whole number in [0, 2^53] from the extension's object; `fallback` where it is absent and
// not required.
double count(const tinygltf::Value& object, const char* key, bool required, double fallback, const std::string& path,
             const std::string& what) {
    if (!object.Has(key)) {
        if (required) throw FileError(path, what + " lacks " + kExtension + "." + key);
        return fallback;
    }
    const tinygltf::Value& value = object.Get(key);
    const double number = value.IsNumber() ? value.GetNumberAsDouble() : -1.0;
    if (!(number >= 0.0) || number > 9007199254740992.0 || number != std::floor(number))
        throw FileError(path, what + ": " + kExtension + "." + key + " must be a whole number, at least 0");
    return number;
}

std::string text(const tinygltf::Value& object, const char* key, const char* fallback, const std::string& path,
                 const std::string& what) {
    if (!object.Has(key)) {
        if (!fallback) throw FileError(path, what + " lacks " + kExtension + "." + key);
        return fallback;
    }
    if (!object.Get(key).IsString()) throw FileError(path, what + ": " + kExtension + "." + key + " must be a string");
    return object.Get(key).Get<std::string>();
}

}  // namespace

std::string withEmptyFallbackBuffers(const std::string& bytes, bool binary) {
    return editGltfJson(bytes, binary, [binary](nlohmann::json& doc) {
        if (!doc.contains("buffers") || !doc["buffers"].is_array() || !doc.contains("bufferViews") ||
            !doc["bufferViews"].is_array())
            return false;
        auto& buffers = doc["buffers"];
        // A buffer is a placeholder when compressed views alone refer to it, and at least one does.
        std::vector<int> compressedUses(buffers.size(), 0), otherUses(buffers.size(), 0);
        for (const auto& view : doc["bufferViews"]) {
            if (!view.is_object() || !view.contains("buffer") || !view["buffer"].is_number_unsigned()) continue;
            const auto index = view["buffer"].get<std::uint64_t>();
            if (index >= buffers.size()) continue;  // the preflight names it
            ++(compressed(view) ? compressedUses : otherUses)[index];
        }
        bool changed = false;
        for (std::size_t b = 0; b < buffers.size(); ++b) {
            auto& buffer = buffers[b];
            if (!buffer.is_object() || buffer.contains("uri")) continue;
            if (binary && b == 0) continue;  // the binary chunk
            if (compressedUses[b] == 0 || otherUses[b] > 0) continue;
            buffer["uri"] = "data:application/octet-stream;base64,AAAAAA==";  // 4 zero bytes: tinygltf refuses none
            buffer["byteLength"] = 4;
            changed = true;
        }
        return changed;
    });
}

void decodeMeshoptBufferViews(tinygltf::Model& model, const std::string& path) {
    for (std::size_t v = 0; v < model.bufferViews.size(); ++v) {
        tinygltf::BufferView& view = model.bufferViews[v];
        const auto found = view.extensions.find(kExtension);
        if (found == view.extensions.end()) continue;
        const std::string what = "bufferViews[" + std::to_string(v) + "]";
        const tinygltf::Value& extension = found->second;
        if (!extension.IsObject()) throw FileError(path, what + ": " + kExtension + " must be an object");

        const double source = count(extension, "buffer", true, 0, path, what);
        const double offset = count(extension, "byteOffset", false, 0, path, what);
        const double length = count(extension, "byteLength", true, 0, path, what);
        const double stride = count(extension, "byteStride", true, 0, path, what);
        const double elements = count(extension, "count", true, 0, path, what);
        const std::string mode = text(extension, "mode", nullptr, path, what);
        const std::string filter = text(extension, "filter", "NONE", path, what);

        if (source >= static_cast<double>(model.buffers.size()))
            throw FileError(path, what + ": " + kExtension + ".buffer is " + std::to_string(std::llround(source)) +
                                      ", but the file has " + std::to_string(model.buffers.size()) + " buffers");
        const std::vector<unsigned char>& data = model.buffers[static_cast<std::size_t>(source)].data;
        if (offset + length > static_cast<double>(data.size()))
            throw FileError(path, what + ": the compressed bytes (" + kExtension + ".byteOffset " +
                                      std::to_string(std::llround(offset)) + ", byteLength " +
                                      std::to_string(std::llround(length)) + ") run past the end of buffer " +
                                      std::to_string(std::llround(source)) + " (" + std::to_string(data.size()) +
                                      " bytes)");
        if (mode != "ATTRIBUTES" && mode != "TRIANGLES" && mode != "INDICES")
            throw FileError(path, what + ": " + kExtension + ".mode '" + mode +
                                      "' is none of ATTRIBUTES, TRIANGLES, INDICES");
        if (filter != "NONE" && filter != "OCTAHEDRAL" && filter != "QUATERNION" && filter != "EXPONENTIAL")
            throw FileError(path, what + ": " + kExtension + ".filter '" + filter +
                                      "' is none of NONE, OCTAHEDRAL, QUATERNION, EXPONENTIAL");
        const std::string rule = [&]() -> std::string {
            if (mode == "ATTRIBUTES" && (stride == 0 || std::fmod(stride, 4.0) != 0 || stride > 256))
                return "with mode ATTRIBUTES, byteStride must be a multiple of 4 from 4 to 256";
            if (mode != "ATTRIBUTES" && stride != 2 && stride != 4)
                return "with mode " + mode + ", byteStride must be 2 or 4";
            if (mode == "TRIANGLES" && std::fmod(elements, 3.0) != 0)
                return "with mode TRIANGLES, count must be a multiple of 3";
            if (mode != "ATTRIBUTES" && filter != "NONE") return "mode " + mode + " takes no filter";
            if (filter == "OCTAHEDRAL" && stride != 4 && stride != 8)
                return "the OCTAHEDRAL filter needs byteStride 4 or 8";
            if (filter == "QUATERNION" && stride != 8) return "the QUATERNION filter needs byteStride 8";
            if (filter == "EXPONENTIAL" && std::fmod(stride, 4.0) != 0)
                return "the EXPONENTIAL filter needs a byteStride that is a multiple of 4";
            if (view.byteStride != 0 && static_cast<double>(view.byteStride) != stride)
                return "byteStride " + std::to_string(std::llround(stride)) + " differs from the buffer view's " +
                       std::to_string(view.byteStride);
            if (static_cast<double>(view.byteLength) != stride * elements)
                return "count x byteStride (" + std::to_string(std::llround(elements)) + " x " +
                       std::to_string(std::llround(stride)) + ") differs from the buffer view's byteLength " +
                       std::to_string(view.byteLength);
            return "";
        }();
        if (!rule.empty()) throw FileError(path, what + ": " + kExtension + ": " + rule);
        const double decodedBytes = stride * elements;
        if (decodedBytes > kLargestView || decodedBytes > kMostBytesPerCompressedByte * length + 64.0)
            throw FileError(path, what + ": " + kExtension + " claims " + std::to_string(std::llround(decodedBytes)) +
                                      " bytes from " + std::to_string(std::llround(length)) +
                                      " compressed bytes, more than the codec can hold");

        const auto n = static_cast<std::size_t>(elements);
        const auto size = static_cast<std::size_t>(stride);
        const unsigned char* compressedBytes = data.data() + static_cast<std::size_t>(offset);
        const auto compressedLength = static_cast<std::size_t>(length);
        std::vector<unsigned char> decoded(n * size);
        int status = 0;
        if (mode == "ATTRIBUTES")
            status = meshopt_decodeVertexBuffer(decoded.data(), n, size, compressedBytes, compressedLength);
        else if (mode == "TRIANGLES")
            status = meshopt_decodeIndexBuffer(decoded.data(), n, size, compressedBytes, compressedLength);
        else
            status = meshopt_decodeIndexSequence(decoded.data(), n, size, compressedBytes, compressedLength);
        if (status != 0)
            throw FileError(path, what + ": the " + kExtension + " data cannot be decoded (mode " + mode + ", " +
                                      std::to_string(n) + " elements of " + std::to_string(size) + " bytes from " +
                                      std::to_string(compressedLength) + " bytes; meshoptimizer's status " +
                                      std::to_string(status) + ")");
        if (filter == "OCTAHEDRAL") meshopt_decodeFilterOct(decoded.data(), n, size);
        if (filter == "QUATERNION") meshopt_decodeFilterQuat(decoded.data(), n, size);
        if (filter == "EXPONENTIAL") meshopt_decodeFilterExp(decoded.data(), n, size);

        tinygltf::Buffer buffer;
        buffer.name = what + " decoded";
        buffer.data = std::move(decoded);
        model.buffers.push_back(std::move(buffer));
        view.buffer = static_cast<int>(model.buffers.size() - 1);
        view.byteOffset = 0;
        view.extensions.erase(found);
    }
}

}  // namespace rad
