#include "scene/gltf_preflight.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <vector>

#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include "util/error.h"

namespace rad {
namespace {

// The JSON chunk of a .glb (its header was checked before): 12-byte header, then the chunk's
// length, type, and bytes.
std::string glbJson(const std::string& bytes) {
    if (bytes.size() < 20) return {};
    const auto* b = reinterpret_cast<const unsigned char*>(bytes.data());
    const std::uint32_t length = b[12] | (b[13] << 8) | (b[14] << 16) | (std::uint32_t(b[15]) << 24);
    if (length > bytes.size() - 20) return {};
    return bytes.substr(20, length);
}

int hexValue(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

std::string percentDecoded(const std::string& uri) {
    std::string out;
    for (std::size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '%' && i + 2 < uri.size() && hexValue(uri[i + 1]) >= 0 && hexValue(uri[i + 2]) >= 0) {
            out += static_cast<char>(hexValue(uri[i + 1]) * 16 + hexValue(uri[i + 2]));
            i += 2;
        } else {
            out += uri[i];
        }
    }
    return out;
}

// Why the URI may not be followed, or empty when it may.
std::string refusal(const std::string& uri) {
    if (uri.rfind("data:", 0) == 0) return {};
    const std::string path = percentDecoded(uri);
    if (path.empty()) return "is empty";
    if (path.find('\0') != std::string::npos) return "contains a NUL character";
    if (path[0] == '/' || path[0] == '\\') return "is an absolute path";
    const std::size_t colon = path.find(':');
    const std::size_t slash = path.find_first_of("/\\");
    if (colon != std::string::npos && (slash == std::string::npos || colon < slash))
        return "names a scheme or drive (" + path.substr(0, colon + 1) + "); only files beside the scene are read";
    int depth = 0;
    std::size_t start = 0;
    while (start <= path.size()) {
        std::size_t end = path.find_first_of("/\\", start);
        if (end == std::string::npos) end = path.size();
        const std::string part = path.substr(start, end - start);
        if (part == "..") {
            if (--depth < 0) return "leaves the scene's directory";
        } else if (!part.empty() && part != ".") {
            ++depth;
        }
        start = end + 1;
    }
    return {};
}

bool insideDirectory(const std::string& file, const std::string& directory) {
    std::error_code ec;
    const std::filesystem::path f = std::filesystem::weakly_canonical(file, ec);
    if (ec) return false;
    const std::filesystem::path d = std::filesystem::weakly_canonical(directory, ec);
    if (ec) return false;
    auto fi = f.begin();
    for (auto di = d.begin(); di != d.end(); ++di, ++fi)
        if (fi == f.end() || *fi != *di) return false;
    return true;
}

bool confinedFileExists(const std::string& file, void* directory) {
    return insideDirectory(file, *static_cast<const std::string*>(directory)) && tinygltf::FileExists(file, nullptr);
}

using Json = nlohmann::json;

const char* typeName(const Json& v) {
    switch (v.type()) {
        case Json::value_t::null: return "null";
        case Json::value_t::object: return "an object";
        case Json::value_t::array: return "an array";
        case Json::value_t::string: return "a string";
        case Json::value_t::boolean: return "a boolean";
        case Json::value_t::number_float: return "a fractional number";
        default: return "a number";
    }
}

// Type rules for one property: what it must be, checked only where present.
enum class Kind { Index, Count, Number, String, Boolean, Object, IndexArray, ObjectArray, StringArray, Numbers };

struct Rule {
    const char* property;
    Kind kind;
    int length;  // Numbers: exact count (0: any)
};

bool isIndex(const Json& v) { return v.is_number_integer() && v.get<long long>() >= 0; }

bool matches(const Json& v, const Rule& rule) {
    switch (rule.kind) {
        case Kind::Index: return isIndex(v);
        case Kind::Count: return isIndex(v);
        case Kind::Number: return v.is_number();
        case Kind::String: return v.is_string();
        case Kind::Boolean: return v.is_boolean();
        case Kind::Object: return v.is_object();
        case Kind::IndexArray:
            return v.is_array() && std::all_of(v.begin(), v.end(), [](const Json& e) { return isIndex(e); });
        case Kind::ObjectArray:
            return v.is_array() && std::all_of(v.begin(), v.end(), [](const Json& e) { return e.is_object(); });
        case Kind::StringArray:
            return v.is_array() && std::all_of(v.begin(), v.end(), [](const Json& e) { return e.is_string(); });
        case Kind::Numbers:
            return v.is_array() && (rule.length == 0 || static_cast<int>(v.size()) == rule.length) &&
                   std::all_of(v.begin(), v.end(), [](const Json& e) { return e.is_number(); });
    }
    return false;
}

std::string expectation(const Rule& rule) {
    switch (rule.kind) {
        case Kind::Index: return "an index (an integer >= 0)";
        case Kind::Count: return "an integer >= 0";
        case Kind::Number: return "a number";
        case Kind::String: return "a string";
        case Kind::Boolean: return "true or false";
        case Kind::Object: return "an object";
        case Kind::IndexArray: return "an array of indices";
        case Kind::ObjectArray: return "an array of objects";
        case Kind::StringArray: return "an array of strings";
        case Kind::Numbers:
            return rule.length > 0 ? "an array of " + std::to_string(rule.length) + " numbers" : "an array of numbers";
    }
    return "";
}

void checkRules(const std::string& path, const Json& object, const std::string& where, std::initializer_list<Rule> rules) {
    for (const Rule& rule : rules) {
        const auto found = object.find(rule.property);
        if (found == object.end() || matches(*found, rule)) continue;
        throw FileError(path, (where.empty() ? "" : where + ".") + rule.property + " must be " + expectation(rule) +
                                  " (it is " + typeName(*found) + ")");
    }
}

// Calls f(element, "name[i]") for every element of the top-level array `name`.
template <typename F>
void forEach(const std::string& path, const Json& document, const char* name, F&& f) {
    const auto list = document.find(name);
    if (list == document.end()) return;
    if (!list->is_array()) throw FileError(path, std::string(name) + " must be an array (it is " + typeName(*list) + ")");
    for (std::size_t i = 0; i < list->size(); ++i) {
        const Json& element = (*list)[i];
        const std::string where = std::string(name) + "[" + std::to_string(i) + "]";
        if (!element.is_object()) throw FileError(path, where + " must be an object (it is " + typeName(element) + ")");
        f(element, where);
    }
}

void checkTypes(const std::string& path, const Json& d) {
    checkRules(path, d, "",
               {{"scene", Kind::Index, 0}, {"extensionsRequired", Kind::StringArray, 0},
                {"extensionsUsed", Kind::StringArray, 0}});
    forEach(path, d, "scenes", [&](const Json& e, const std::string& w) { checkRules(path, e, w, {{"nodes", Kind::IndexArray, 0}}); });
    forEach(path, d, "nodes", [&](const Json& e, const std::string& w) {
        checkRules(path, e, w,
                   {{"children", Kind::IndexArray, 0}, {"mesh", Kind::Index, 0}, {"camera", Kind::Index, 0},
                    {"matrix", Kind::Numbers, 16}, {"translation", Kind::Numbers, 3}, {"rotation", Kind::Numbers, 4},
                    {"scale", Kind::Numbers, 3}, {"name", Kind::String, 0}});
    });
    forEach(path, d, "meshes", [&](const Json& e, const std::string& w) {
        checkRules(path, e, w, {{"primitives", Kind::ObjectArray, 0}, {"name", Kind::String, 0}});
        if (!e.contains("primitives")) return;
        for (std::size_t p = 0; p < e["primitives"].size(); ++p) {
            const Json& primitive = e["primitives"][p];
            const std::string where = w + ".primitives[" + std::to_string(p) + "]";
            checkRules(path, primitive, where,
                       {{"attributes", Kind::Object, 0}, {"indices", Kind::Index, 0}, {"material", Kind::Index, 0},
                        {"mode", Kind::Index, 0}});
            if (primitive.contains("attributes"))
                for (const auto& [name, value] : primitive["attributes"].items())
                    if (!isIndex(value))
                        throw FileError(path, where + ".attributes." + name + " must be an accessor index (it is " +
                                                  typeName(value) + ")");
        }
    });
    forEach(path, d, "accessors", [&](const Json& e, const std::string& w) {
        checkRules(path, e, w,
                   {{"bufferView", Kind::Index, 0}, {"byteOffset", Kind::Count, 0}, {"componentType", Kind::Index, 0},
                    {"count", Kind::Count, 0}, {"type", Kind::String, 0}, {"normalized", Kind::Boolean, 0},
                    {"sparse", Kind::Object, 0}});
    });
    forEach(path, d, "bufferViews", [&](const Json& e, const std::string& w) {
        checkRules(path, e, w,
                   {{"buffer", Kind::Index, 0}, {"byteOffset", Kind::Count, 0}, {"byteLength", Kind::Count, 0},
                    {"byteStride", Kind::Count, 0}});
    });
    forEach(path, d, "buffers", [&](const Json& e, const std::string& w) {
        checkRules(path, e, w, {{"byteLength", Kind::Count, 0}, {"uri", Kind::String, 0}});
    });
    forEach(path, d, "images", [&](const Json& e, const std::string& w) { checkRules(path, e, w, {{"uri", Kind::String, 0}}); });
    forEach(path, d, "materials", [&](const Json& e, const std::string& w) {
        checkRules(path, e, w,
                   {{"emissiveFactor", Kind::Numbers, 3}, {"doubleSided", Kind::Boolean, 0},
                    {"pbrMetallicRoughness", Kind::Object, 0}, {"name", Kind::String, 0}});
        if (e.contains("pbrMetallicRoughness"))
            checkRules(path, e["pbrMetallicRoughness"], w + ".pbrMetallicRoughness", {{"baseColorFactor", Kind::Numbers, 4}});
    });
    forEach(path, d, "cameras", [&](const Json& e, const std::string& w) {
        checkRules(path, e, w, {{"type", Kind::String, 0}, {"perspective", Kind::Object, 0}, {"orthographic", Kind::Object, 0}});
    });
}

void checkUris(const std::string& path, const Json& document) {
    for (const char* kind : {"buffers", "images"}) {
        const auto list = document.find(kind);
        if (list == document.end() || !list->is_array()) continue;
        for (std::size_t i = 0; i < list->size(); ++i) {
            const Json& entry = (*list)[i];
            if (!entry.is_object() || !entry.contains("uri") || !entry["uri"].is_string()) continue;
            const std::string uri = entry["uri"].get<std::string>();
            const std::string why = refusal(uri);
            if (!why.empty()) {
                const std::string shown = uri.size() > 80 ? uri.substr(0, 80) + "..." : uri;
                throw FileError(path, std::string(kind).substr(0, std::string(kind).size() - 1) + " " + std::to_string(i) +
                                          " has the external URI '" + shown + "', which " + why + ": refused");
            }
        }
    }
}

}  // namespace

void preflightGltf(const std::string& path, const std::string& bytes, bool binary) {
    const Json document = Json::parse(binary ? glbJson(bytes) : bytes, nullptr, false);
    if (document.is_discarded() || !document.is_object()) return;
    checkTypes(path, document);
    checkUris(path, document);
}

tinygltf::FsCallbacks confinedFileSystem(const std::string& directory) {
    tinygltf::FsCallbacks fs;
    fs.FileExists = confinedFileExists;
    fs.ExpandFilePath = tinygltf::ExpandFilePath;
    fs.ReadWholeFile = tinygltf::ReadWholeFile;
    fs.WriteWholeFile = tinygltf::WriteWholeFile;
    fs.user_data = const_cast<std::string*>(&directory);
    return fs;
}

}  // namespace rad
