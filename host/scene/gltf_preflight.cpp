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
        const std::string shown = found->is_number() ? found->dump() : typeName(*found);
        throw FileError(path, (where.empty() ? "" : where + ".") + rule.property + " must be " + expectation(rule) +
                                  " (it is " + shown + ")");
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

// The size of the top-level array `name` (0 when absent or not an array).
std::size_t countOf(const Json& document, const char* name) {
    const auto list = document.find(name);
    return list != document.end() && list->is_array() ? list->size() : 0;
}

// An index property, where present, must name an element of the top-level array `target`.
void checkReference(const std::string& path, const Json& object, const std::string& where, const char* property,
                    const Json& document, const char* target) {
    const auto found = object.find(property);
    if (found == object.end() || !isIndex(*found)) return;
    const auto index = found->get<long long>();
    if (index >= static_cast<long long>(countOf(document, target)))
        throw FileError(path, where + "." + property + " is " + std::to_string(index) + ", but there " +
                                  (countOf(document, target) == 1 ? "is " : "are ") +
                                  std::to_string(countOf(document, target)) + " " + target);
}

// The object extensions[name] of `parent`, or null when absent.
const Json* extensionOf(const Json& parent, const char* name) {
    const auto extensions = parent.find("extensions");
    if (extensions == parent.end() || !extensions->is_object()) return nullptr;
    const auto found = extensions->find(name);
    return found == extensions->end() ? nullptr : &*found;
}

void checkExtensionObject(const std::string& path, const Json* extension, const std::string& where,
                          std::initializer_list<Rule> rules) {
    if (!extension) return;
    if (!extension->is_object())
        throw FileError(path, where + " must be an object (it is " + typeName(*extension) + ")");
    checkRules(path, *extension, where, rules);
}

// A textureInfo (baseColorTexture, emissiveTexture, ...), where present.
void checkTextureInfo(const std::string& path, const Json& parent, const std::string& where, const char* property,
                      const Json& document) {
    const auto found = parent.find(property);
    if (found == parent.end()) return;
    const std::string at = where + "." + property;
    if (!found->is_object()) throw FileError(path, at + " must be an object (it is " + typeName(*found) + ")");
    checkRules(path, *found, at,
               {{"index", Kind::Index, 0},
                {"texCoord", Kind::Count, 0},
                {"scale", Kind::Number, 0},
                {"strength", Kind::Number, 0}});
    // (inside a material extension's object, which the document-wide walk leaves to its reader)
    const auto extensions = found->find("extensions");
    if (extensions != found->end() && !extensions->is_object())
        throw FileError(path, at + ".extensions must be an object (it is " + typeName(*extensions) + ")");
    checkExtensionObject(path, extensionOf(*found, "KHR_texture_transform"), at + ".extensions.KHR_texture_transform",
                         {{"offset", Kind::Numbers, 2},
                          {"rotation", Kind::Number, 0},
                          {"scale", Kind::Numbers, 2},
                          {"texCoord", Kind::Count, 0}});
    if (!found->contains("index")) throw FileError(path, at + " has no index");
    checkReference(path, *found, at, "index", document, "textures");
}

// Everywhere in the document (except inside `extras`, which is the author's own): `name` is a
// string and `extensions` an object, as the schema's glTFProperty and glTFChildOfRootProperty say.
void checkNamesAndExtensions(const std::string& path, const Json& value, const std::string& where, int depth) {
    if (depth > 64) return;  // checkNesting refused deeper files; this only bounds the walk
    if (value.is_array()) {
        for (std::size_t i = 0; i < value.size(); ++i)
            checkNamesAndExtensions(path, value[i], where + "[" + std::to_string(i) + "]", depth + 1);
        return;
    }
    if (!value.is_object()) return;
    for (const auto& [key, child] : value.items()) {
        const std::string at = where.empty() ? key : where + "." + key;
        if (key == "extras") continue;
        if (key == "name" && !child.is_string())
            throw FileError(path, at + " must be a string (it is " + typeName(child) + ")");
        if (key == "extensions") {
            if (!child.is_object()) throw FileError(path, at + " must be an object (it is " + typeName(child) + ")");
            continue;  // each extension's own rules (below, for those the loader reads) say what its keys mean
        }
        checkNamesAndExtensions(path, child, at, depth + 1);
    }
}

// asset.version: "2.x". A glTF 1.0 file is another format and would be misread.
void checkAsset(const std::string& path, const Json& d) {
    const auto asset = d.find("asset");
    if (asset == d.end()) throw FileError(path, "has no asset object (every glTF 2.0 file states asset.version)");
    if (!asset->is_object())
        throw FileError(path, std::string("asset must be an object (it is ") + typeName(*asset) + ")");
    const auto version = asset->find("version");
    if (version == asset->end() || !version->is_string())
        throw FileError(path, "asset.version must be a string such as \"2.0\"");
    for (const char* property : {"version", "minVersion"}) {
        const auto found = asset->find(property);
        if (found == asset->end()) continue;
        if (!found->is_string()) throw FileError(path, std::string("asset.") + property + " must be a string");
        const std::string text = found->get<std::string>();
        const std::size_t dot = text.find('.');
        const bool wellFormed = dot != std::string::npos && dot > 0 && dot + 1 < text.size() &&
                                std::all_of(text.begin(), text.begin() + static_cast<long>(dot), ::isdigit) &&
                                std::all_of(text.begin() + static_cast<long>(dot) + 1, text.end(), ::isdigit);
        if (!wellFormed)
            throw FileError(path, std::string("asset.") + property + " '" + text + "' is not a version (major.minor)");
        if (text.substr(0, dot) != "2")
            throw FileError(path, std::string("asset.") + property + " is '" + text +
                                      "': only glTF 2.x is supported (glTF 1.0 is a different format)");
    }
}

void checkTypes(const std::string& path, const Json& d) {
    checkAsset(path, d);
    checkNamesAndExtensions(path, d, "", 0);
    checkRules(path, d, "",
               {{"scene", Kind::Index, 0}, {"extensionsRequired", Kind::StringArray, 0},
                {"extensionsUsed", Kind::StringArray, 0}});
    forEach(path, d, "scenes", [&](const Json& e, const std::string& w) { checkRules(path, e, w, {{"nodes", Kind::IndexArray, 0}}); });
    forEach(path, d, "nodes", [&](const Json& e, const std::string& w) {
        checkRules(path, e, w,
                   {{"children", Kind::IndexArray, 0},
                    {"mesh", Kind::Index, 0},
                    {"camera", Kind::Index, 0},
                    {"skin", Kind::Index, 0},
                    {"matrix", Kind::Numbers, 16},
                    {"translation", Kind::Numbers, 3},
                    {"rotation", Kind::Numbers, 4},
                    {"scale", Kind::Numbers, 3},
                    {"weights", Kind::Numbers, 0}});
        checkExtensionObject(path, extensionOf(e, "KHR_lights_punctual"), w + ".extensions.KHR_lights_punctual",
                             {{"light", Kind::Index, 0}});
    });
    forEach(path, d, "meshes", [&](const Json& e, const std::string& w) {
        checkRules(path, e, w, {{"primitives", Kind::ObjectArray, 0}, {"weights", Kind::Numbers, 0}});
        if (!e.contains("primitives")) return;
        for (std::size_t p = 0; p < e["primitives"].size(); ++p) {
            const Json& primitive = e["primitives"][p];
            const std::string where = w + ".primitives[" + std::to_string(p) + "]";
            checkRules(path, primitive, where,
                       {{"attributes", Kind::Object, 0},
                        {"indices", Kind::Index, 0},
                        {"material", Kind::Index, 0},
                        {"mode", Kind::Index, 0},
                        {"targets", Kind::ObjectArray, 0}});
            if (primitive.contains("attributes"))
                for (const auto& [name, value] : primitive["attributes"].items())
                    if (!isIndex(value))
                        throw FileError(path, where + ".attributes." + name + " must be an accessor index (it is " +
                                                  typeName(value) + ")");
        }
    });
    forEach(path, d, "accessors", [&](const Json& e, const std::string& w) {
        checkRules(path, e, w,
                   {{"bufferView", Kind::Index, 0},
                    {"byteOffset", Kind::Count, 0},
                    {"componentType", Kind::Index, 0},
                    {"count", Kind::Count, 0},
                    {"type", Kind::String, 0},
                    {"normalized", Kind::Boolean, 0},
                    {"sparse", Kind::Object, 0},
                    {"min", Kind::Numbers, 0},
                    {"max", Kind::Numbers, 0}});
    });
    forEach(path, d, "bufferViews", [&](const Json& e, const std::string& w) {
        checkRules(path, e, w,
                   {{"buffer", Kind::Index, 0},
                    {"byteOffset", Kind::Count, 0},
                    {"byteLength", Kind::Count, 0},
                    {"byteStride", Kind::Count, 0},
                    {"target", Kind::Count, 0}});
    });
    forEach(path, d, "buffers", [&](const Json& e, const std::string& w) {
        checkRules(path, e, w, {{"byteLength", Kind::Count, 0}, {"uri", Kind::String, 0}});
    });
    forEach(path, d, "images", [&](const Json& e, const std::string& w) {
        checkRules(path, e, w,
                   {{"uri", Kind::String, 0}, {"bufferView", Kind::Index, 0}, {"mimeType", Kind::String, 0}});
        checkReference(path, e, w, "bufferView", d, "bufferViews");
    });
    forEach(path, d, "textures", [&](const Json& e, const std::string& w) {
        checkRules(path, e, w, {{"sampler", Kind::Index, 0}, {"source", Kind::Index, 0}});
        checkReference(path, e, w, "sampler", d, "samplers");
        checkReference(path, e, w, "source", d, "images");
    });
    forEach(path, d, "samplers", [&](const Json& e, const std::string& w) {
        checkRules(path, e, w,
                   {{"magFilter", Kind::Count, 0},
                    {"minFilter", Kind::Count, 0},
                    {"wrapS", Kind::Count, 0},
                    {"wrapT", Kind::Count, 0}});
        const auto oneOf = [&](const char* property, std::initializer_list<long long> allowed) {
            const auto found = e.find(property);
            if (found == e.end()) return;
            const long long v = found->get<long long>();
            if (std::find(allowed.begin(), allowed.end(), v) == allowed.end())
                throw FileError(path, w + "." + property + " is " + std::to_string(v) + ", which glTF does not define");
        };
        oneOf("magFilter", {9728, 9729});
        oneOf("minFilter", {9728, 9729, 9984, 9985, 9986, 9987});
        oneOf("wrapS", {33071, 33648, 10497});
        oneOf("wrapT", {33071, 33648, 10497});
    });
    forEach(path, d, "materials", [&](const Json& e, const std::string& w) {
        checkRules(path, e, w,
                   {{"emissiveFactor", Kind::Numbers, 3},
                    {"doubleSided", Kind::Boolean, 0},
                    {"pbrMetallicRoughness", Kind::Object, 0},
                    {"alphaMode", Kind::String, 0},
                    {"alphaCutoff", Kind::Number, 0}});
        const auto alphaMode = e.find("alphaMode");
        if (alphaMode != e.end() && *alphaMode != "OPAQUE" && *alphaMode != "MASK" && *alphaMode != "BLEND")
            throw FileError(path, w + ".alphaMode must be OPAQUE, MASK or BLEND (it is " + alphaMode->dump() + ")");
        const auto cutoff = e.find("alphaCutoff");
        if (cutoff != e.end() && !(cutoff->get<double>() >= 0.0))
            throw FileError(path, w + ".alphaCutoff must be >= 0");
        for (const char* texture : {"emissiveTexture", "normalTexture", "occlusionTexture"})
            checkTextureInfo(path, e, w, texture, d);
        if (e.contains("pbrMetallicRoughness")) {
            const Json& pbr = e["pbrMetallicRoughness"];
            const std::string at = w + ".pbrMetallicRoughness";
            checkRules(path, pbr, at,
                       {{"baseColorFactor", Kind::Numbers, 4},
                        {"metallicFactor", Kind::Number, 0},
                        {"roughnessFactor", Kind::Number, 0}});
            checkTextureInfo(path, pbr, at, "baseColorTexture", d);
            checkTextureInfo(path, pbr, at, "metallicRoughnessTexture", d);
        }
        const std::string ext = w + ".extensions.";
        checkExtensionObject(path, extensionOf(e, "KHR_materials_emissive_strength"),
                             ext + "KHR_materials_emissive_strength", {{"emissiveStrength", Kind::Number, 0}});
        checkExtensionObject(path, extensionOf(e, "KHR_materials_ior"), ext + "KHR_materials_ior",
                             {{"ior", Kind::Number, 0}});
        checkExtensionObject(path, extensionOf(e, "KHR_materials_volume"), ext + "KHR_materials_volume",
                             {{"thicknessFactor", Kind::Number, 0},
                              {"attenuationDistance", Kind::Number, 0},
                              {"attenuationColor", Kind::Numbers, 3}});
        const Json* specular = extensionOf(e, "KHR_materials_specular");
        checkExtensionObject(path, specular, ext + "KHR_materials_specular",
                             {{"specularFactor", Kind::Number, 0}, {"specularColorFactor", Kind::Numbers, 3}});
        if (specular) {
            checkTextureInfo(path, *specular, ext + "KHR_materials_specular", "specularTexture", d);
            checkTextureInfo(path, *specular, ext + "KHR_materials_specular", "specularColorTexture", d);
        }
        const Json* transmission = extensionOf(e, "KHR_materials_transmission");
        checkExtensionObject(path, transmission, ext + "KHR_materials_transmission",
                             {{"transmissionFactor", Kind::Number, 0}});
        if (transmission)
            checkTextureInfo(path, *transmission, ext + "KHR_materials_transmission", "transmissionTexture", d);
    });
    forEach(path, d, "cameras", [&](const Json& e, const std::string& w) {
        checkRules(path, e, w, {{"type", Kind::String, 0}, {"perspective", Kind::Object, 0}, {"orthographic", Kind::Object, 0}});
        if (e.contains("perspective"))
            checkRules(path, e["perspective"], w + ".perspective",
                       {{"yfov", Kind::Number, 0},
                        {"aspectRatio", Kind::Number, 0},
                        {"znear", Kind::Number, 0},
                        {"zfar", Kind::Number, 0}});
        if (e.contains("orthographic"))
            checkRules(path, e["orthographic"], w + ".orthographic",
                       {{"xmag", Kind::Number, 0},
                        {"ymag", Kind::Number, 0},
                        {"znear", Kind::Number, 0},
                        {"zfar", Kind::Number, 0}});
    });
    // KHR_lights_punctual's lights, and every node's reference to one.
    const Json* lights = extensionOf(d, "KHR_lights_punctual");
    checkExtensionObject(path, lights, "extensions.KHR_lights_punctual", {{"lights", Kind::ObjectArray, 0}});
    const std::size_t lightCount = lights && lights->contains("lights") ? (*lights)["lights"].size() : 0;
    if (lights && lights->contains("lights"))
        for (std::size_t i = 0; i < lightCount; ++i) {
            const Json& light = (*lights)["lights"][i];
            const std::string w = "extensions.KHR_lights_punctual.lights[" + std::to_string(i) + "]";
            checkRules(path, light, w,
                       {{"type", Kind::String, 0},
                        {"color", Kind::Numbers, 3},
                        {"intensity", Kind::Number, 0},
                        {"range", Kind::Number, 0},
                        {"spot", Kind::Object, 0},
                        {"name", Kind::String, 0}});
            if (!light.contains("type")) throw FileError(path, w + " has no type");
            if (light["type"] == "spot" && !light.contains("spot"))
                throw FileError(path, w + " is a spot light without its spot object");
            if (light.contains("spot"))
                checkRules(path, light["spot"], w + ".spot",
                           {{"innerConeAngle", Kind::Number, 0}, {"outerConeAngle", Kind::Number, 0}});
        }
    forEach(path, d, "nodes", [&](const Json& e, const std::string& w) {
        const Json* placed = extensionOf(e, "KHR_lights_punctual");
        if (!placed) return;
        if (!placed->contains("light")) throw FileError(path, w + ".extensions.KHR_lights_punctual has no light");
        const auto index = (*placed)["light"].get<long long>();
        if (index >= static_cast<long long>(lightCount))
            throw FileError(path, w + " places light " + std::to_string(index) + ", but the file defines " +
                                      std::to_string(lightCount) + " (extensions.KHR_lights_punctual.lights)");
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

// How deeply the JSON text nests arrays and objects, outside strings. The parsers recurse (tinygltf
// crashed on 200,000 nested arrays in `extras`), so a file nested deeper than any glTF needs is
// refused before either sees it.
void checkNesting(const std::string& path, const std::string& text) {
    constexpr int kDeepest = 512;
    int depth = 0;
    bool inString = false, escaped = false;
    for (const char c : text) {
        if (inString) {
            if (escaped) escaped = false;
            else if (c == '\\') escaped = true;
            else if (c == '"') inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            if (++depth > kDeepest)
                throw FileError(path, "nests JSON arrays and objects deeper than " + std::to_string(kDeepest) + " levels");
        } else if (c == ']' || c == '}') {
            --depth;
        }
    }
}

}  // namespace

void preflightGltf(const std::string& path, const std::string& bytes, bool binary) {
    const std::string text = binary ? glbJson(bytes) : bytes;
    checkNesting(path, text);
    const Json document = Json::parse(text, nullptr, false);
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
