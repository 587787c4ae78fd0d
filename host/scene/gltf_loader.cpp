#include "scene/gltf_loader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <unordered_map>

#include <tiny_gltf.h>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

#include "scene/gltf_accessor.h"
#include "scene/gltf_draco.h"
#include "scene/gltf_meshopt.h"
#include "scene/gltf_lights.h"
#include "scene/gltf_preflight.h"
#include "scene/gltf_textures.h"
#include "scene/image_decode.h"
#include "scene/tangents.h"
#include "scene/material_model.h"
#include "scene/world_surfaces.h"
#include "util/error.h"

namespace rad {
namespace {

// Extensions this loader honours. Anything else required is refused by name; anything else used
// is named in a warning (the scene loads, without what the extension adds).
const std::set<std::string> kSupported = {
    "KHR_materials_emissive_strength",
    "KHR_mesh_quantization",
    "KHR_materials_unlit",    // reflectance still comes from the base colour; no specular layer
    "KHR_texture_transform",  // scene/gltf_textures.cpp
    "KHR_lights_punctual",
    "KHR_materials_transmission",  // kept in the material (scene/material_model.h)
    "KHR_materials_ior",
    "KHR_materials_specular",  // its factors: the specular layer's strength and tint (material_model.h)
    "KHR_materials_volume",  // thicknessFactor: whether transmitted light refracts; its attenuation
    "KHR_draco_mesh_compression",  // scene/gltf_draco.cpp
    "EXT_meshopt_compression",     // scene/gltf_meshopt.cpp
    "EXT_mesh_gpu_instancing",     // a node's mesh once per instance (addNode)
    "EXT_texture_webp",            // scene/gltf_textures.cpp, scene/image_decode.cpp
};

constexpr int kMaxNodeDepth = 1024;

// tinygltf's messages can span lines and quote whole base64 data URIs: make them one line
// of reasonable length.
std::string oneLine(std::string text) {
    std::replace(text.begin(), text.end(), '\n', ' ');
    while (!text.empty() && (text.back() == ' ' || text.back() == '\r')) text.pop_back();
    for (std::size_t at = text.find("base64,"); at != std::string::npos; at = text.find("base64,", at + 1)) {
        const std::size_t start = at + 7;
        std::size_t end = start;
        while (end < text.size() && text[end] != ' ' && text[end] != '\'' && text[end] != '"') ++end;
        if (end - start > 16) text.replace(start, end - start, "...");
    }
    constexpr std::size_t kLongest = 400;
    if (text.size() > kLongest) text = text.substr(0, kLongest) + "...";
    return text;
}

bool allFinite(const std::vector<double>& values) {
    return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
}

bool hasGlbExtension(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension == ".glb";
}

// Binary glTF: a 12-byte header (magic "glTF", version, total length) and chunks. Checked here
// because tinygltf's messages for these cases do not say what is wrong.
bool checkBinaryHeader(const std::string& path, const std::string& bytes) {
    const bool magic = bytes.size() >= 4 && bytes.compare(0, 4, "glTF") == 0;
    if (!magic && !hasGlbExtension(path)) return false;  // a JSON .gltf
    if (!magic) throw FileError(path, "not a binary glTF file (bad magic; expected \"glTF\")");
    if (bytes.size() < 12) throw FileError(path, "truncated binary glTF: the 12-byte header is incomplete");
    const auto* h = reinterpret_cast<const unsigned char*>(bytes.data());
    const std::uint32_t declared = h[8] | (h[9] << 8) | (h[10] << 16) | (std::uint32_t(h[11]) << 24);
    if (bytes.size() < declared)
        throw FileError(path, "truncated binary glTF: the header says " + std::to_string(declared) +
                                  " bytes, the file has " + std::to_string(bytes.size()));
    return true;
}

tinygltf::Model parse(const std::string& path, const std::string& bytes, std::vector<std::string>& warnings) {
    const bool binary = checkBinaryHeader(path, bytes);
    preflightGltf(path, bytes, binary);
    std::string directory = std::filesystem::path(path).parent_path().string();
    if (directory.empty()) directory = ".";
    tinygltf::TinyGLTF parser;
    long long imageBudget = kMostImageTexels;  // for all of the file's images together
    parser.SetImageLoader(decodeGltfImage, &imageBudget);
    parser.SetFsCallbacks(confinedFileSystem(directory));
    tinygltf::Model model;
    std::string err, warn;
    bool ok = false;
    const std::string parsed = withEmptyFallbackBuffers(withoutCompressedIndices(bytes, binary), binary);
    try {
        const auto* data = reinterpret_cast<const unsigned char*>(parsed.data());
        ok = binary ? parser.LoadBinaryFromMemory(&model, &err, &warn, data, static_cast<unsigned int>(parsed.size()),
                                                  directory)
                    : parser.LoadASCIIFromString(&model, &err, &warn, parsed.data(),
                                                 static_cast<unsigned int>(parsed.size()), directory);
    } catch (const std::exception& e) {  // nlohmann::json throws on some malformed input
        throw FileError(path, std::string("malformed glTF JSON: ") + oneLine(e.what()));
    }
    if (!ok || !err.empty()) {
        std::string message = oneLine(err.empty() ? warn : err);
        if (message.empty()) message = "unreadable glTF";
        throw FileError(path, (binary ? "cannot load binary glTF: " : "cannot load glTF: ") + message);
    }
    if (!warn.empty()) warnings.push_back(oneLine(warn));
    decodeMeshoptBufferViews(model, path);
    return model;
}

void checkExtensions(const tinygltf::Model& model, const std::string& path, std::vector<std::string>& warnings) {
    for (const std::string& name : model.extensionsRequired)
        if (kSupported.count(name) == 0) throw FileError(path, "requires the unsupported extension " + name);
    std::string ignored;
    for (const std::string& name : model.extensionsUsed)
        if (kSupported.count(name) == 0) ignored += (ignored.empty() ? "" : ", ") + name;
    if (!ignored.empty()) warnings.push_back("extensions not supported, so ignored: " + ignored);
}

glm::vec3 factor3(const std::vector<double>& values, glm::vec3 fallback) {
    if (values.size() < 3) return fallback;
    return {static_cast<float>(values[0]), static_cast<float>(values[1]), static_cast<float>(values[2])};
}

// A number from a material extension: its default when absent; refused when not a finite
// number; clamped into [lo, hi] with a warning when outside.
float extensionNumber(const tinygltf::Value& extension, const char* property, float fallback, float lo, float hi,
                      const std::string& what, const std::string& path, std::vector<std::string>& warnings) {
    if (!extension.IsObject() || !extension.Has(property)) return fallback;
    const tinygltf::Value& value = extension.Get(property);
    const double v = value.IsNumber() ? value.GetNumberAsDouble() : std::nan("");
    if (!std::isfinite(v)) throw FileError(path, what + ": " + property + " must be a finite number");
    if (v < lo || v > hi) {
        warnings.push_back(what + ": " + property + " " + std::to_string(v) + " lies outside [" + std::to_string(lo) +
                           ", " + std::to_string(hi) + "] and was clamped");
        return static_cast<float>(std::clamp(v, static_cast<double>(lo), static_cast<double>(hi)));
    }
    return static_cast<float>(v);
}

// A material extension's texture reference (a textureInfo inside the extension's object, which
// tinygltf leaves as plain values) as the core's TextureInfo; index -1 where it has none. The
// preflight checked its index, texCoord and KHR_texture_transform (gltf_preflight.cpp).
tinygltf::TextureInfo extensionTextureInfo(const tinygltf::Value& extension, const char* property) {
    tinygltf::TextureInfo info;
    if (!extension.IsObject() || !extension.Has(property)) return info;
    const tinygltf::Value& value = extension.Get(property);
    if (!value.IsObject()) return info;
    if (value.Has("index") && value.Get("index").IsNumber())
        info.index = static_cast<int>(value.Get("index").GetNumberAsInt());
    if (value.Has("texCoord") && value.Get("texCoord").IsNumber())
        info.texCoord = static_cast<int>(value.Get("texCoord").GetNumberAsInt());
    if (value.Has("extensions") && value.Get("extensions").IsObject()) {
        const tinygltf::Value& extensions = value.Get("extensions");
        for (const std::string& key : extensions.Keys()) info.extensions[key] = extensions.Get(key);
    }
    return info;
}

float unitFactor(double value, const char* property, const std::string& what, const std::string& path,
                 std::vector<std::string>& warnings) {
    if (!std::isfinite(value)) throw FileError(path, what + " has a non-finite " + property);
    if (value < 0.0 || value > 1.0) {
        warnings.push_back(what + ": " + property + " outside [0, 1] clamped");
        return static_cast<float>(std::clamp(value, 0.0, 1.0));
    }
    return static_cast<float>(value);
}

Material convertMaterial(const tinygltf::Material& source, std::size_t index, const std::string& path,
                         const GltfTextures& textures, std::vector<std::string>& warnings) {
    Material m;
    m.name = source.name.empty() ? "material" + std::to_string(index) : source.name;
    const std::string what = "material " + std::to_string(index) + " ('" + m.name + "')";
    const auto& pbr = source.pbrMetallicRoughness;
    if (!allFinite(pbr.baseColorFactor) || !allFinite(source.emissiveFactor))
        throw FileError(path, what + " has a non-finite colour factor");
    m.baseColor = factor3(pbr.baseColorFactor, glm::vec3(1.0f));
    m.emission = factor3(source.emissiveFactor, glm::vec3(0.0f));
    auto strength = source.extensions.find("KHR_materials_emissive_strength");
    if (strength != source.extensions.end() && strength->second.Has("emissiveStrength")) {
        const tinygltf::Value& value = strength->second.Get("emissiveStrength");
        const double s = value.IsNumber() ? value.GetNumberAsDouble() : -1.0;
        if (!std::isfinite(s) || s < 0.0)
            throw FileError(path, what + " has an emissive strength that is not a finite number >= 0");
        m.emission *= static_cast<float>(s);
    }
    if (glm::any(glm::lessThan(m.baseColor, glm::vec3(0.0f))) ||
        glm::any(glm::greaterThan(m.baseColor, glm::vec3(1.0f)))) {
        warnings.push_back(what + ": base colour outside [0, 1] clamped (a reflectance above 1 creates energy)");
        m.baseColor = glm::clamp(m.baseColor, 0.0f, 1.0f);
    }
    if (glm::any(glm::lessThan(m.emission, glm::vec3(0.0f))))
        throw FileError(path, what + " has a negative emissive factor");
    // pi Le is the exitance; radiosity adds to it. Keep both well inside single precision.
    if (!(m.emission.x < 1e36f && m.emission.y < 1e36f && m.emission.z < 1e36f))
        throw FileError(path, what + " emits a radiance beyond what single precision can hold (1e36)");
    m.doubleSided = source.doubleSided;

    // glTF's defaults: metallicFactor 1, roughnessFactor 1 (tinygltf fills them in when absent).
    m.metallic = unitFactor(pbr.metallicFactor, "metallicFactor", what, path, warnings);
    m.roughness = unitFactor(pbr.roughnessFactor, "roughnessFactor", what, path, warnings);
    m.metallicRoughnessTextured = pbr.metallicRoughnessTexture.index >= 0;
    const auto transmission = source.extensions.find("KHR_materials_transmission");
    if (transmission != source.extensions.end()) {
        m.transmission =
            extensionNumber(transmission->second, "transmissionFactor", 0.0f, 0.0f, 1.0f, what, path, warnings);
        if (transmission->second.IsObject() && transmission->second.Has("transmissionTexture"))
            warnings.push_back(what + ": transmissionTexture is not read yet; its transmissionFactor alone is used");
    }
    const auto ior = source.extensions.find("KHR_materials_ior");
    if (ior != source.extensions.end()) {
        m.ior = extensionNumber(ior->second, "ior", 1.5f, 0.0f, 1e6f, what, path, warnings);
        if (m.ior > 0.0f && m.ior < 1.0f)
            throw FileError(
                path, what + ": KHR_materials_ior's ior must be 0 or at least 1 (it is " + std::to_string(m.ior) + ")");
    }
    const auto volume = source.extensions.find("KHR_materials_volume");
    if (volume != source.extensions.end()) {
        m.thickness = extensionNumber(volume->second, "thicknessFactor", 0.0f, 0.0f, 1e30f, what, path, warnings);
        if (volume->second.IsObject() && volume->second.Has("attenuationDistance")) {
            const tinygltf::Value& d = volume->second.Get("attenuationDistance");
            const double v = d.IsNumber() ? d.GetNumberAsDouble() : std::nan("");
            if (!std::isfinite(v) || v <= 0.0)
                throw FileError(path, what + ": KHR_materials_volume's attenuationDistance must be a finite number > 0");
            m.attenuationDistance = static_cast<float>(v);
        }
        if (volume->second.IsObject() && volume->second.Has("attenuationColor")) {
            const tinygltf::Value& colour = volume->second.Get("attenuationColor");
            for (int c = 0; c < 3; ++c) {
                const double v = colour.Get(c).IsNumber() ? colour.Get(c).GetNumberAsDouble() : std::nan("");
                if (!std::isfinite(v) || v < 0.0 || v > 1.0)
                    throw FileError(path, what + ": KHR_materials_volume's attenuationColor must be three numbers "
                                                 "from 0 to 1");
                m.attenuationColor[c] = static_cast<float>(v);
            }
        }
        if (volume->second.IsObject() && volume->second.Has("thicknessTexture"))
            warnings.push_back(what + ": KHR_materials_volume's thicknessTexture is not read (the solid's own "
                                      "geometry sets how far light goes inside it)");
    }
    // glTF's specular layer: on by default (factor 1, colour white), KHR_materials_specular
    // weakens or tints it
    m.specular = 1.0f;
    const auto layer = source.extensions.find("KHR_materials_specular");
    if (layer != source.extensions.end()) {
        m.specular = extensionNumber(layer->second, "specularFactor", 1.0f, 0.0f, 1.0f, what, path, warnings);
        if (layer->second.IsObject() && layer->second.Has("specularColorFactor")) {
            const tinygltf::Value& colour = layer->second.Get("specularColorFactor");
            for (int c = 0; c < 3; ++c) {
                const double v = colour.Get(c).IsNumber() ? colour.Get(c).GetNumberAsDouble() : std::nan("");
                if (!std::isfinite(v) || v < 0.0)
                    throw FileError(path, what + ": KHR_materials_specular's specularColorFactor must be three "
                                                 "finite numbers >= 0");
                m.specularColor[c] = static_cast<float>(v);
            }
        }
        if (layer->second.IsObject()) {
            m.specularTexture = textures.reference(extensionTextureInfo(layer->second, "specularTexture"), what,
                                                   "KHR_materials_specular's specularTexture");
            m.specularTexture.linear = true;  // the alpha channel, which is linear anyway
            m.specularColorTexture = textures.reference(extensionTextureInfo(layer->second, "specularColorTexture"),
                                                        what, "KHR_materials_specular's specularColorTexture");
        }
    }
    if (source.extensions.count("KHR_materials_unlit")) {
        // shown by its base colour alone: plain diffuse, no layer, no metal
        m.specular = 0.0f;
        m.metallic = 0.0f;
    }
    m.reflectance = plainReflectance(m);
    m.reflectance = radiosityReflectance(m);  // with the layer, where it has one
    const SpecularKind specular = specularKind(m);
    // KHR_materials_specular's textures shape a non-metal's layer; where there is none to shape (a
    // mirror, a rough metal, glass, specularFactor 0, unlit) they are dropped, not averaged
    if (specular != SpecularKind::none || m.specular == 0.0f) {
        if (specular == SpecularKind::glass && (m.specularTexture.present() || m.specularColorTexture.present()))
            warnings.push_back(what + ": KHR_materials_specular's textures are not read on glass: its reflection "
                                      "is its ior's (docs/guide/materials.md)");
        m.specularTexture = TextureRef{};
        m.specularColorTexture = TextureRef{};
    }
    if (m.metallic > 0.0f)
        warnings.push_back(
            what + ": metallicFactor " + std::to_string(m.metallic) +
            (pbr.metallicFactor == 1.0 ? " (glTF's default when absent)" : "") +
            (specular == SpecularKind::mirror
                 ? ": a mirror: the progressive solve, the camera pass and the path tracer follow its "
                   "reflection; the matrix solvers carry it as diffuse light (docs/guide/materials.md)"
             : specular == SpecularKind::glossy
                 ? ": a rough metal: the progressive solve, the camera pass and the path tracer follow its "
                   "GGX reflection; the matrix solvers carry it as diffuse light (docs/guide/materials.md)"
             : m.metallicRoughnessTextured
                 ? " under a metallicRoughnessTexture: the camera pass and the path tracer draw the metal where "
                   "the texture says, texel by texel, in its specular layer; the radiosity pass reflects it "
                   "diffusely (docs/guide/materials.md)"
                 : ": partly metal: the camera pass and the path tracer draw the metal's reflection in its "
                   "specular layer; the radiosity pass reflects it diffusely (docs/guide/materials.md)"));
    if (m.transmission > 0.0f)
        warnings.push_back(
            what + ": transmissionFactor " + std::to_string(m.transmission) +
            (specular == SpecularKind::glass
                 ? std::string(m.roughness > kSmoothSurface ? ": rough glass (GGX microfacets)" : ": glass") +
                       ": the progressive solve, the camera pass and the path tracer follow its reflection and "
                       "refraction; the matrix solvers take it as opaque (docs/guide/materials.md)"
                 : ": transmitted light is absorbed, the surface is opaque (docs/guide/materials.md)"));

    m.baseColorTexture = textures.reference(pbr.baseColorTexture, what, "baseColorTexture");
    m.emissiveTexture = textures.reference(source.emissiveTexture, what, "emissiveTexture");
    m.metallicRoughnessTexture = textures.reference(pbr.metallicRoughnessTexture, what, "metallicRoughnessTexture");
    m.metallicRoughnessTexture.linear = true;
    if (m.metallicRoughnessTexture.present() && specular == SpecularKind::glass)
        warnings.push_back(what +
                           ": metallicRoughnessTexture is not read on glass: its roughness is roughnessFactor's, " +
                           std::to_string(m.roughness) + ", everywhere (docs/guide/materials.md)");
    if (source.normalTexture.index >= 0) {
        tinygltf::TextureInfo normal;
        normal.index = source.normalTexture.index;
        normal.texCoord = source.normalTexture.texCoord;
        normal.extensions = source.normalTexture.extensions;
        m.normalTexture = textures.reference(normal, what, "normalTexture");
        m.normalTexture.linear = true;
        if (!std::isfinite(source.normalTexture.scale))
            throw FileError(path, what + ": normalTexture's scale is not a finite number");
        m.normalScale = static_cast<float>(source.normalTexture.scale);
        const glm::mat3& t = m.normalTexture.transform;  // columns: KHR_texture_transform's u and v axes
        if (m.normalTexture.present() && (std::abs(t[1][0]) > 1e-6f || std::abs(t[0][1]) > 1e-6f ||
                                          !(t[0][0] > 0.0f) || !(t[1][1] > 0.0f)))
            warnings.push_back(what +
                               ": normalTexture's KHR_texture_transform turns or mirrors it: its normals are read in "
                               "the tangent frame of the untransformed coordinates, so they point elsewhere");
    }
    // Alpha: MASK cuts the surface where alpha < alphaCutoff; BLEND (partial transparency) has no
    // place in opaque light transport, so it is read as MASK at 0.5.
    m.alpha = pbr.baseColorFactor.size() == 4 ? static_cast<float>(std::clamp(pbr.baseColorFactor[3], 0.0, 1.0)) : 1.0f;
    if (source.alphaMode == "MASK") {
        if (!std::isfinite(source.alphaCutoff) || source.alphaCutoff < 0.0)
            throw FileError(path, what + " has an alphaCutoff that is not a finite number >= 0");
        m.alphaMode = Material::AlphaMode::Mask;
        m.alphaCutoff = static_cast<float>(source.alphaCutoff);
    } else if (source.alphaMode == "BLEND") {
        m.alphaMode = Material::AlphaMode::Mask;
        m.alphaCutoff = 0.5f;
        warnings.push_back(what +
                           ": alphaMode BLEND is read as MASK with alphaCutoff 0.5 (light passes where alpha < 0.5)");
    }
    return m;
}

glm::dmat4 localTransform(const tinygltf::Node& node, int index, const std::string& path) {
    const std::string what = "node " + std::to_string(index);
    if (!node.matrix.empty()) {
        if (node.matrix.size() != 16 || !allFinite(node.matrix))
            throw FileError(path, what + " has a matrix that is not 16 finite numbers");
        glm::dmat4 m;
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) m[c][r] = node.matrix[static_cast<std::size_t>(4 * c + r)];
        return m;
    }
    glm::dmat4 m(1.0);
    if (!node.translation.empty()) {
        if (node.translation.size() != 3 || !allFinite(node.translation))
            throw FileError(path, what + " has a translation that is not 3 finite numbers");
        m[3] = glm::dvec4(node.translation[0], node.translation[1], node.translation[2], 1.0);
    }
    if (!node.rotation.empty()) {
        if (node.rotation.size() != 4 || !allFinite(node.rotation))
            throw FileError(path, what + " has a rotation that is not 4 finite numbers");
        glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);  // w, x, y, z
        const double length = glm::length(q);
        if (length < 1e-12) throw FileError(path, what + " has a zero rotation quaternion");
        m = m * glm::mat4_cast(q / length);
    }
    if (!node.scale.empty()) {
        if (node.scale.size() != 3 || !allFinite(node.scale))
            throw FileError(path, what + " has a scale that is not 3 finite numbers");
        m = m * glm::dmat4(glm::dvec4(node.scale[0], 0, 0, 0), glm::dvec4(0, node.scale[1], 0, 0),
                           glm::dvec4(0, 0, node.scale[2], 0), glm::dvec4(0, 0, 0, 1));
    }
    return m;
}

// A node reached from the scene's roots with its world transform.
struct PlacedNode {
    int index;
    glm::dmat4 world;
};

// A skinned node's mesh as the file poses it (glTF 3.7.3): each vertex moved by its joints'
// matrices (a joint's world transform times its inverse bind matrix), weighted by WEIGHTS_n; the
// node's own transform is ignored. `placed` (the node's transform, times an instance's) is what
// a primitive the skin cannot move (no JOINTS_0, or Draco-compressed) is drawn in instead.
struct SkinPose {
    std::vector<glm::dmat4> joints;
    glm::dmat4 placed;
};

// Walks the node forest from the scene's roots. Refuses what the spec forbids and what would
// make the walk endless: indices out of range, nodes with two parents, cycles, absurd depth.
std::vector<PlacedNode> placeNodes(const tinygltf::Model& model, const std::string& path) {
    const int nodeCount = static_cast<int>(model.nodes.size());
    std::vector<int> parent(static_cast<std::size_t>(nodeCount), -1);
    for (int n = 0; n < nodeCount; ++n)
        for (int child : model.nodes[static_cast<std::size_t>(n)].children) {
            if (child < 0 || child >= nodeCount)
                throw FileError(path, "node " + std::to_string(n) + " has child " + std::to_string(child) +
                                          ", which does not exist");
            if (child == n) throw FileError(path, "node " + std::to_string(n) + " is its own child (a node cycle)");
            if (parent[static_cast<std::size_t>(child)] >= 0)
                throw FileError(path, "node " + std::to_string(child) + " has two parents (nodes " +
                                          std::to_string(parent[static_cast<std::size_t>(child)]) + " and " +
                                          std::to_string(n) + "); glTF node hierarchies must be trees");
            parent[static_cast<std::size_t>(child)] = n;
        }

    std::vector<int> roots;
    int sceneIndex = model.defaultScene >= 0 ? model.defaultScene : (model.scenes.empty() ? -1 : 0);
    if (sceneIndex >= static_cast<int>(model.scenes.size()))
        throw FileError(path, "the default scene " + std::to_string(sceneIndex) + " does not exist");
    if (sceneIndex >= 0) {
        roots = model.scenes[static_cast<std::size_t>(sceneIndex)].nodes;
    } else {
        for (int n = 0; n < nodeCount; ++n)
            if (parent[static_cast<std::size_t>(n)] < 0) roots.push_back(n);
    }

    std::vector<PlacedNode> placed;
    std::vector<char> seen(static_cast<std::size_t>(nodeCount), 0);
    struct Pending {
        int index;
        glm::dmat4 parentWorld;
        int depth;
    };
    std::vector<Pending> stack;
    for (auto it = roots.rbegin(); it != roots.rend(); ++it) {
        const int root = *it;
        if (root < 0 || root >= nodeCount)
            throw FileError(path, "the scene lists node " + std::to_string(root) + ", which does not exist");
        stack.push_back({root, glm::dmat4(1.0), 0});
    }
    while (!stack.empty()) {
        const Pending item = stack.back();
        stack.pop_back();
        const auto slot = static_cast<std::size_t>(item.index);
        if (seen[slot])
            throw FileError(path, "node " + std::to_string(item.index) +
                                      " is reached twice from the scene's roots (a node cycle, or a root that is also a child)");
        seen[slot] = 1;
        if (item.depth > kMaxNodeDepth)
            throw FileError(path, "the node hierarchy is deeper than " + std::to_string(kMaxNodeDepth) + " levels");
        const tinygltf::Node& node = model.nodes[slot];
        const glm::dmat4 world = item.parentWorld * localTransform(node, item.index, path);
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r)
                if (!std::isfinite(world[c][r]))
                    throw FileError(path, "the world transform of node " + std::to_string(item.index) + " is not finite");
        placed.push_back({item.index, world});
        for (auto child = node.children.rbegin(); child != node.children.rend(); ++child)
            stack.push_back({*child, world, item.depth + 1});
    }
    // A cycle that no root reaches is still a malformed file. Each node has at most one parent,
    // so following parents from every node, marking the way, finds any cycle in linear time.
    std::vector<int> walk(static_cast<std::size_t>(nodeCount), -1);  // which start node marked it
    for (int start = 0; start < nodeCount; ++start) {
        for (int n = start; n >= 0 && walk[static_cast<std::size_t>(n)] < 0; n = parent[static_cast<std::size_t>(n)]) {
            walk[static_cast<std::size_t>(n)] = start;
            const int up = parent[static_cast<std::size_t>(n)];
            if (up >= 0 && walk[static_cast<std::size_t>(up)] == start)
                throw FileError(path, "node " + std::to_string(up) + " lies on a node cycle");
        }
    }
    return placed;
}

std::string primitiveName(const tinygltf::Mesh& mesh, int meshIndex, std::size_t primitive) {
    return "mesh " + std::to_string(meshIndex) + (mesh.name.empty() ? "" : " ('" + mesh.name + "')") + " primitive " +
           std::to_string(primitive);
}

// Vertex index triples of the primitive's triangles, in glTF's winding.
std::vector<std::array<std::uint32_t, 3>> assembleTriangles(int mode, const std::vector<std::uint32_t>& index) {
    std::vector<std::array<std::uint32_t, 3>> triangles;
    const std::size_t n = index.size();
    if (mode == TINYGLTF_MODE_TRIANGLES) {
        for (std::size_t i = 0; i + 2 < n; i += 3) triangles.push_back({index[i], index[i + 1], index[i + 2]});
    } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
        // glTF: triangle i is (v_i, v_{i+1+i%2}, v_{i+2-i%2}), which keeps the winding consistent.
        for (std::size_t i = 0; i + 2 < n; ++i)
            triangles.push_back({index[i], index[i + 1 + i % 2], index[i + 2 - i % 2]});
    } else if (mode == TINYGLTF_MODE_TRIANGLE_FAN) {
        // glTF: triangle i is (v_{i+1}, v_{i+2}, v_0).
        for (std::size_t i = 0; i + 2 < n; ++i) triangles.push_back({index[i + 1], index[i + 2], index[0]});
    }
    return triangles;
}

class SceneBuilder {
public:
    SceneBuilder(const tinygltf::Model& model, const std::string& path, Scene& scene)
        : model_(model),
          path_(path),
          scene_(scene),
          lights_(model, path, scene.warnings),
          textures_(model, scene.warnings) {}

    void addMaterials() {
        scene_.images = textures_.images();
        for (std::size_t i = 0; i < model_.materials.size(); ++i)
            scene_.materials.push_back(convertMaterial(model_.materials[i], i, path_, textures_, scene_.warnings));
    }

    // Every placed node's world transform, for the joints of skins (addNode).
    void knowPlacements(const std::vector<PlacedNode>& nodes) {
        for (const PlacedNode& n : nodes) nodeWorld_[n.index] = n.world;
    }

    void addNode(const PlacedNode& placed) {
        const tinygltf::Node& node = model_.nodes[static_cast<std::size_t>(placed.index)];
        if (node.camera >= 0) addCamera(node, placed);
        if (std::optional<Light> light = lights_.place(node, placed.index, placed.world))
            placedLights_.push_back(*light);
        if (node.mesh < 0) return;
        if (node.mesh >= static_cast<int>(model_.meshes.size()))
            throw FileError(path_, "node " + std::to_string(placed.index) + " uses mesh " + std::to_string(node.mesh) +
                                       ", which does not exist");
        const tinygltf::Mesh& mesh = model_.meshes[static_cast<std::size_t>(node.mesh)];
        const std::string name = node.name.empty() ? "node" + std::to_string(placed.index) : node.name;
        const std::optional<std::vector<glm::dmat4>> joints = skinJoints(node, placed.index);
        const std::vector<glm::dmat4> instances = instanceTransforms(node, name);
        // A skin places the mesh by its joints alone; an instance's transform still applies.
        auto place = [&](const std::string& surfaceName, const glm::dmat4& instance) {
            if (!joints) {
                addMesh(placed, node, mesh, surfaceName, placed.world * instance, nullptr);
                return;
            }
            const SkinPose skin{*joints, placed.world * instance};
            addMesh(placed, node, mesh, surfaceName, instance, &skin);
        };
        if (instances.empty()) {
            place(name, glm::dmat4(1.0));
            return;
        }
        // EXT_mesh_gpu_instancing: the mesh once per instance, each a surface of its own.
        for (std::size_t i = 0; i < instances.size(); ++i) place(name + "#" + std::to_string(i), instances[i]);
    }

    // The joint matrices of the node's skin (each joint's world transform times its inverse bind
    // matrix, the identity where the skin gives none), or none: the node has no skin, or a joint
    // lies outside the scene (a warning says so, and the mesh is drawn in the node's transform).
    std::optional<std::vector<glm::dmat4>> skinJoints(const tinygltf::Node& node, int nodeIndex) {
        if (node.skin < 0) return std::nullopt;
        const std::string what = "node " + std::to_string(nodeIndex) + (node.name.empty() ? "" : " ('" + node.name + "')");
        if (node.skin >= static_cast<int>(model_.skins.size()))
            throw FileError(path_, what + " uses skin " + std::to_string(node.skin) + ", which does not exist");
        const tinygltf::Skin& skin = model_.skins[static_cast<std::size_t>(node.skin)];
        const std::string skinName = "skin " + std::to_string(node.skin) + (skin.name.empty() ? "" : " ('" + skin.name + "')");
        if (skin.joints.empty()) throw FileError(path_, skinName + " lists no joints");
        std::vector<glm::dmat4> inverseBind(skin.joints.size(), glm::dmat4(1.0));
        if (skin.inverseBindMatrices >= 0) {
            try {
                inverseBind = readMatrices(model_, {skin.inverseBindMatrices, "inverseBindMatrices of " + skinName});
            } catch (const InputError& e) {
                throw FileError(path_, e.what());
            }
            if (inverseBind.size() < skin.joints.size())
                throw FileError(path_, "inverseBindMatrices of " + skinName + " has " +
                                           std::to_string(inverseBind.size()) + " matrices for " +
                                           std::to_string(skin.joints.size()) + " joints");
        }
        std::vector<glm::dmat4> joints(skin.joints.size());
        for (std::size_t j = 0; j < skin.joints.size(); ++j) {
            const int joint = skin.joints[j];
            if (joint < 0 || joint >= static_cast<int>(model_.nodes.size()))
                throw FileError(path_, skinName + " lists joint node " + std::to_string(joint) + ", which does not exist");
            const auto world = nodeWorld_.find(joint);
            if (world == nodeWorld_.end()) {
                scene_.warnings.push_back(what + ": joint node " + std::to_string(joint) + " of its " + skinName +
                                          " is not in the scene, so the skin is not applied; its mesh is drawn in "
                                          "the node's transform");
                return std::nullopt;
            }
            joints[j] = world->second * inverseBind[j];
        }
        return joints;
    }

    // The transforms of EXT_mesh_gpu_instancing's instances of a node (TRANSLATION, ROTATION and
    // SCALE, each per instance, applied in that order's reverse as a node's TRS), or none.
    std::vector<glm::dmat4> instanceTransforms(const tinygltf::Node& node, const std::string& name) {
        const auto found = node.extensions.find("EXT_mesh_gpu_instancing");
        if (found == node.extensions.end() || !found->second.IsObject() || !found->second.Has("attributes"))
            return {};
        const tinygltf::Value& attributes = found->second.Get("attributes");
        const std::string what = "EXT_mesh_gpu_instancing of node '" + name + "'";
        if (!attributes.IsObject()) throw FileError(path_, what + ": attributes must be an object");
        auto accessorOf = [&](const char* key) {
            if (!attributes.Has(key)) return -1;
            const tinygltf::Value& v = attributes.Get(key);
            if (!v.IsInt() || v.GetNumberAsInt() < 0)
                throw FileError(path_, what + ": " + key + " must be an accessor index");
            return v.GetNumberAsInt();
        };
        std::vector<glm::dvec3> translation, scale;
        std::vector<glm::dvec4> rotation;
        try {
            if (const int a = accessorOf("TRANSLATION"); a >= 0)
                translation = readPositions(model_, {a, "TRANSLATION of " + what});
            if (const int a = accessorOf("SCALE"); a >= 0) scale = readPositions(model_, {a, "SCALE of " + what});
            if (const int a = accessorOf("ROTATION"); a >= 0)
                rotation = readTangents(model_, {a, "ROTATION of " + what});  // VEC4, float or normalized
        } catch (const FileError&) {
            throw;
        } catch (const InputError& e) {
            throw FileError(path_, e.what());
        }
        const std::size_t count = std::max({translation.size(), scale.size(), rotation.size()});
        // Each instance is a copy of the mesh here: bounded, as accessors' counts are.
        std::size_t triangles = 0;
        for (const tinygltf::Primitive& primitive : model_.meshes[static_cast<std::size_t>(node.mesh)].primitives)
            if (primitive.indices >= 0 && static_cast<std::size_t>(primitive.indices) < model_.accessors.size())
                triangles += model_.accessors[static_cast<std::size_t>(primitive.indices)].count / 3;
        if (count > (std::size_t{1} << 20) || count * std::max<std::size_t>(triangles, 1) > (std::size_t{1} << 28))
            throw FileError(path_, what + ": " + std::to_string(count) + " instances of " + std::to_string(triangles) +
                                       " triangles are more than the program copies (2^28 triangles, 2^20 instances)");
        for (const std::size_t n : {translation.size(), scale.size(), rotation.size()})
            if (n != 0 && n != count)
                throw FileError(path_, what + ": its attributes have " + std::to_string(n) + " and " +
                                           std::to_string(count) + " entries");
        std::vector<glm::dmat4> out(count, glm::dmat4(1.0));
        for (std::size_t i = 0; i < count; ++i) {
            glm::dmat4& m = out[i];
            if (!translation.empty()) m[3] = glm::dvec4(translation[i], 1.0);
            if (!rotation.empty()) {
                const glm::dquat q(rotation[i].w, rotation[i].x, rotation[i].y, rotation[i].z);
                const double length = glm::length(q);
                if (length < 1e-12)
                    throw FileError(path_, what + ": instance " + std::to_string(i) + " has a zero rotation");
                m = m * glm::mat4_cast(q / length);
            }
            if (!scale.empty())
                m = m * glm::dmat4(glm::dvec4(scale[i].x, 0, 0, 0), glm::dvec4(0, scale[i].y, 0, 0),
                                   glm::dvec4(0, 0, scale[i].z, 0), glm::dvec4(0, 0, 0, 1));
        }
        return out;
    }

    // world: the mesh's transform, or with a skin, what follows the skin's (an instance's).
    void addMesh(const PlacedNode& placed, const tinygltf::Node& node, const tinygltf::Mesh& mesh,
                 const std::string& name, const glm::dmat4& world, const SkinPose* skin) {
        WorldSurface building;
        building.surface.node = placed.index;
        building.surface.name = uniqueName(name, placed.index);
        const bool mirrored = glm::determinant(glm::dmat3(world)) < 0.0;
        // Morph targets in their default pose: the node's weights, else the mesh's, else none.
        const std::vector<double>& weights = node.weights.empty() ? mesh.weights : node.weights;
        for (std::size_t p = 0; p < mesh.primitives.size(); ++p)
            addPrimitive(building, mesh.primitives[p], primitiveName(mesh, node.mesh, p), world, mirrored, weights,
                         skin);
        if (!building.surface.triangles.empty()) building_.push_back(std::move(building));
    }

    // The surfaces relative to the scene's centre (scene/world_surfaces.h), then the cameras and
    // lights, placed in the same frame.
    void finish() {
        if (skippedPrimitives_ > 0)
            scene_.warnings.push_back(std::to_string(skippedPrimitives_) +
                                      " point or line primitive(s) skipped: only triangles take part");
        placeSurfaces(building_, path_, scene_);
        for (Surface& surface : scene_.surfaces) frameNormalMaps(surface, scene_.materials);
        for (const auto& [camera, world] : cameras_) {
            Camera placed = camera;
            placed.position = relativeToOrigin(world, scene_, path_, "camera '" + camera.name + "'");
            scene_.cameras.push_back(placed);
        }
        for (Light light : placedLights_) {
            light.position -= scene_.origin;
            if (!(std::fabs(light.position.x) < 1e37 && std::fabs(light.position.y) < 1e37 &&
                  std::fabs(light.position.z) < 1e37))
                throw FileError(path_, "light '" + light.name + "' lies beyond single precision from the scene");
            scene_.lights.push_back(light);
        }
        if (scene_.surfaces.empty()) throw FileError(path_, "the scene has no triangles");
    }

private:
    std::string uniqueName(const std::string& name, int node) {
        if (usedNames_.insert(name).second) return name;
        std::string unique = name + "@" + std::to_string(node);
        usedNames_.insert(unique);
        return unique;
    }

    int materialIndex(int gltfMaterial, const std::string& what) {
        if (gltfMaterial >= static_cast<int>(model_.materials.size()) || gltfMaterial < -1)
            throw FileError(path_, what + " uses material " + std::to_string(gltfMaterial) + ", which does not exist");
        if (gltfMaterial >= 0) return gltfMaterial;
        if (defaultMaterial_ < 0) {
            defaultMaterial_ = static_cast<int>(scene_.materials.size());
            scene_.materials.push_back(rad::defaultMaterial());
        }
        return defaultMaterial_;
    }

    // Adds each morph target's displacements of POSITION, NORMAL and TANGENT (xyz), times its
    // weight, to the primitive's attributes (glTF 3.7.2.2).
    void applyMorphTargets(const tinygltf::Primitive& primitive, const std::string& what,
                           const std::vector<double>& weights, std::vector<glm::dvec3>& positions,
                           std::vector<glm::dvec3>& normals, std::vector<glm::dvec4>& tangents) {
        for (std::size_t t = 0; t < primitive.targets.size(); ++t) {
            const double w = t < weights.size() ? weights[t] : 0.0;
            if (w == 0.0) continue;
            if (!std::isfinite(w))
                throw FileError(path_, what + ": the weight of morph target " + std::to_string(t) + " is not finite");
            const std::string target = "morph target " + std::to_string(t) + " of " + what;
            for (const auto& [name, accessor] : primitive.targets[t]) {
                if (name != "POSITION" && name != "NORMAL" && name != "TANGENT") continue;
                if (accessor >= 0 && static_cast<std::size_t>(accessor) < model_.accessors.size() &&
                    model_.accessors[static_cast<std::size_t>(accessor)].bufferView < 0 &&
                    !model_.accessors[static_cast<std::size_t>(accessor)].sparse.isSparse)
                    continue;  // no data: zeros, as glTF defines, which move nothing
                const std::vector<glm::dvec3> delta = readPositions(model_, {accessor, name + " of " + target});
                const std::size_t count = name == "POSITION" ? positions.size()
                                          : name == "NORMAL"   ? normals.size()
                                                               : tangents.size();
                if (count == 0) continue;  // the primitive has no such attribute to displace
                if (delta.size() != count)
                    throw FileError(path_, name + " of " + target + " has " + std::to_string(delta.size()) +
                                               " entries for " + std::to_string(count) + " vertices");
                for (std::size_t i = 0; i < count; ++i) {
                    if (name == "POSITION") positions[i] += w * delta[i];
                    if (name == "NORMAL") normals[i] += w * delta[i];
                    if (name == "TANGENT") tangents[i] += glm::dvec4(w * delta[i], 0.0);
                }
            }
        }
    }

    // Each vertex's transform under the skin: after = the transform that follows the skin's (an
    // instance's), times the joints' matrices weighted by WEIGHTS_n over the sets JOINTS_n the
    // primitive has (the weights taken over their sum, as viewers do where a file's do not add up
    // to 1). Where the skin cannot move the primitive (no JOINTS_0 or WEIGHTS_0, a Draco-compressed
    // one, or a vertex of no weight), skin.placed, with a warning.
    std::vector<glm::dmat4> skinTransforms(const tinygltf::Primitive& primitive, const std::string& what,
                                           const SkinPose& skin, const glm::dmat4& after, bool draco,
                                           std::size_t vertices) {
        std::vector<glm::dmat4> out(vertices, skin.placed);
        const bool hasSet = primitive.attributes.count("JOINTS_0") > 0 && primitive.attributes.count("WEIGHTS_0") > 0;
        if (draco || !hasSet) {
            scene_.warnings.push_back(what + (draco ? " is Draco-compressed" : " has no JOINTS_0 and WEIGHTS_0") +
                                      ": its node's skin does not move it; it is drawn in the node's transform");
            return out;
        }
        std::vector<glm::dmat4> sum(vertices, glm::dmat4(0.0));
        std::vector<double> total(vertices, 0.0);
        for (int set = 0;; ++set) {
            const auto joints = primitive.attributes.find("JOINTS_" + std::to_string(set));
            const auto weights = primitive.attributes.find("WEIGHTS_" + std::to_string(set));
            if (joints == primitive.attributes.end() || weights == primitive.attributes.end()) break;
            const std::string jointsName = "JOINTS_" + std::to_string(set) + " of " + what;
            const std::string weightsName = "WEIGHTS_" + std::to_string(set) + " of " + what;
            const std::vector<std::array<std::uint32_t, 4>> j = readJoints(model_, {joints->second, jointsName});
            const std::vector<glm::dvec4> w = readWeights(model_, {weights->second, weightsName});
            if (j.size() != vertices || w.size() != vertices)
                throw FileError(path_, jointsName + " and its weights have " + std::to_string(j.size()) + " and " +
                                           std::to_string(w.size()) + " entries for " + std::to_string(vertices) +
                                           " vertices");
            for (std::size_t v = 0; v < vertices; ++v)
                for (int k = 0; k < 4; ++k) {
                    if (w[v][k] == 0.0) continue;
                    if (j[v][static_cast<std::size_t>(k)] >= skin.joints.size())
                        throw FileError(path_, jointsName + ": vertex " + std::to_string(v) + " names joint " +
                                                   std::to_string(j[v][static_cast<std::size_t>(k)]) + " of a skin of " +
                                                   std::to_string(skin.joints.size()));
                    sum[v] += w[v][k] * skin.joints[j[v][static_cast<std::size_t>(k)]];
                    total[v] += w[v][k];
                }
        }
        std::size_t weightless = 0;
        for (std::size_t v = 0; v < vertices; ++v) {
            if (total[v] > 0.0) out[v] = after * (sum[v] / total[v]);
            else ++weightless;
        }
        if (weightless > 0)
            scene_.warnings.push_back(what + ": " + std::to_string(weightless) +
                                      " vertices have no skin weight; they are drawn in the node's transform");
        return out;
    }

    void addPrimitive(WorldSurface& building, const tinygltf::Primitive& primitive, const std::string& what,
                      const glm::dmat4& world, bool mirrored, const std::vector<double>& weights,
                      const SkinPose* skin) {
        Surface& surface = building.surface;
        // Each vertex's transform where a skin moves them (else `world` for all).
        std::vector<glm::dmat4> skinned;
        int mode = primitive.mode < 0 ? TINYGLTF_MODE_TRIANGLES : primitive.mode;
        if (mode == TINYGLTF_MODE_POINTS || mode == TINYGLTF_MODE_LINE || mode == TINYGLTF_MODE_LINE_LOOP ||
            mode == TINYGLTF_MODE_LINE_STRIP) {
            ++skippedPrimitives_;
            return;
        }
        if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP && mode != TINYGLTF_MODE_TRIANGLE_FAN)
            throw FileError(path_, what + " has unknown mode " + std::to_string(mode));
        const auto position = primitive.attributes.find("POSITION");
        if (position == primitive.attributes.end()) throw FileError(path_, what + " has no POSITION attribute");

        std::vector<glm::dvec3> local;
        std::vector<std::uint32_t> index;
        std::array<std::vector<glm::dvec2>, 2> uv;
        std::vector<glm::dvec3> normals;
        std::vector<glm::dvec4> tangents;
        std::vector<glm::dvec3> colors;
        // A Draco-compressed primitive holds its positions, the attributes it lists and its
        // triangles in the compressed view; it decodes to a triangle list.
        const bool draco = isDracoCompressed(primitive);
        try {
            DecodedPrimitive decoded;
            if (draco) {
                if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP)
                    throw FileError(path_, what + " is Draco-compressed with mode " + std::to_string(mode) +
                                               ": the extension allows triangles or a triangle strip only");
                decoded = decodeDracoPrimitive(model_, primitive, what);
                mode = TINYGLTF_MODE_TRIANGLES;
                local = std::move(decoded.positions);
                normals = std::move(decoded.normals);
                uv = std::move(decoded.texCoords);
                colors = std::move(decoded.colors);
            } else {
                local = readPositions(model_, {position->second, "POSITION of " + what});
            }
            for (std::size_t set = 0; set < uv.size(); ++set) {
                const std::string name = "TEXCOORD_" + std::to_string(set);
                const auto found = primitive.attributes.find(name);
                if (found == primitive.attributes.end() || !uv[set].empty()) continue;
                uv[set] = readTexCoords(model_, {found->second, name + " of " + what});
                if (uv[set].size() != local.size())
                    throw FileError(path_, name + " of " + what + " has " + std::to_string(uv[set].size()) +
                                               " entries for " + std::to_string(local.size()) + " vertices");
            }
            const auto normal = primitive.attributes.find("NORMAL");
            if (normal != primitive.attributes.end() && normals.empty()) {
                normals = readNormals(model_, {normal->second, "NORMAL of " + what});
                if (normals.size() != local.size())
                    throw FileError(path_, "NORMAL of " + what + " has " + std::to_string(normals.size()) +
                                               " entries for " + std::to_string(local.size()) + " vertices");
            }
            const auto tangent = primitive.attributes.find("TANGENT");
            if (tangent != primitive.attributes.end() && draco)
                scene_.warnings.push_back("TANGENT of " + what +
                                          " is Draco-compressed and not decoded: a normal map there is drawn in "
                                          "generated tangents");
            if (tangent != primitive.attributes.end() && !draco) {
                tangents = readTangents(model_, {tangent->second, "TANGENT of " + what});
                if (tangents.size() != local.size())
                    throw FileError(path_, "TANGENT of " + what + " has " + std::to_string(tangents.size()) +
                                               " entries for " + std::to_string(local.size()) + " vertices");
            }
            const auto color = primitive.attributes.find("COLOR_0");
            if (color != primitive.attributes.end() && colors.empty()) {  // not in the Draco data
                colors = readColors(model_, {color->second, "COLOR_0 of " + what});
                if (colors.size() != local.size())
                    throw FileError(path_, "COLOR_0 of " + what + " has " + std::to_string(colors.size()) +
                                               " entries for " + std::to_string(local.size()) + " vertices");
            }
            if (!draco) applyMorphTargets(primitive, what, weights, local, normals, tangents);
            else if (!primitive.targets.empty())
                scene_.warnings.push_back(what + " is Draco-compressed: its morph targets are not applied");
            if (skin != nullptr) skinned = skinTransforms(primitive, what, *skin, world, draco, local.size());
            if (draco) {
                index = std::move(decoded.triangles);
            } else if (primitive.indices >= 0) {
                index = readIndices(model_, {primitive.indices, "indices of " + what});
            } else {
                index.resize(local.size());
                for (std::size_t i = 0; i < index.size(); ++i) index[i] = static_cast<std::uint32_t>(i);
            }
        } catch (const FileError&) {
            throw;
        } catch (const InputError& e) {
            throw FileError(path_, e.what());
        }
        for (std::size_t i = 0; i < index.size(); ++i)
            if (index[i] >= local.size())
                throw FileError(path_, "index " + std::to_string(index[i]) + " at position " + std::to_string(i) +
                                           " of " + what + " is out of range (" + std::to_string(local.size()) +
                                           " vertices)");
        const int material = materialIndex(primitive.material, what);
        {
            const Material& m = scene_.materials[static_cast<std::size_t>(material)];
            for (const TextureRef* ref : {&m.baseColorTexture, &m.emissiveTexture, &m.normalTexture})
                if (ref->present() && uv[static_cast<std::size_t>(ref->texCoord)].empty())
                    scene_.warnings.push_back(what + " has material '" + m.name + "', whose texture reads TEXCOORD_" +
                                              std::to_string(ref->texCoord) +
                                              ", which it lacks: the texture's (0, 0) texel covers it");
        }

        const auto base = static_cast<std::uint32_t>(building.world.size());
        // Texture coordinates, where this primitive or an earlier one of the surface has them;
        // vertices without them read (0, 0).
        for (std::size_t set = 0; set < uv.size(); ++set) {
            std::vector<glm::vec2>& coords = surface.texCoords[set];
            if (uv[set].empty() && coords.empty()) continue;
            coords.resize(base, glm::vec2(0.0f));
            if (uv[set].empty())
                coords.resize(base + local.size(), glm::vec2(0.0f));
            else
                for (const glm::dvec2& t : uv[set]) coords.emplace_back(t);
        }
        // Vertex colours, where this primitive or an earlier one of the surface has them; vertices
        // without them take white, which leaves the base colour as it is.
        if (!colors.empty() || !surface.colors.empty()) {
            surface.colors.resize(base, glm::vec3(1.0f));
            if (colors.empty())
                surface.colors.resize(base + local.size(), glm::vec3(1.0f));
            else
                for (const glm::dvec3& c : colors) surface.colors.emplace_back(c);
        }
        // Normals, by the inverse transpose of the node's linear part; where this primitive has
        // none but an earlier one of the surface had, (0, 0, 0): shaded flat.
        if (!normals.empty() || !surface.normals.empty()) {
            surface.normals.resize(base, glm::vec3(0.0f));
            const glm::dmat3 toWorld = glm::transpose(glm::inverse(glm::dmat3(world)));
            bool zero = false;
            for (std::size_t i = 0; i < local.size(); ++i) {
                const glm::dmat3 normalTransform =
                    skinned.empty() ? toWorld : glm::transpose(glm::inverse(glm::dmat3(skinned[i])));
                glm::dvec3 n = normals.empty() ? glm::dvec3(0.0) : normalTransform * normals[i];
                const double length = glm::length(n);
                if (!normals.empty() && !(length > 1e-12 && std::isfinite(length))) zero = true;
                surface.normals.emplace_back(length > 1e-12 && std::isfinite(length) ? n / length : glm::dvec3(0.0));
            }
            if (zero)
                scene_.warnings.push_back("NORMAL of " + what +
                                          " has zero-length normals: the faces around those vertices are shaded flat");
        }
        // Tangents, by the node's linear part, the bitangent's sign flipped where it mirrors;
        // where this primitive has none, w = 0 (generated in finish() where a normal map needs them).
        if (!tangents.empty() || !surface.tangents.empty()) {
            surface.tangents.resize(base, glm::vec4(0.0f));
            for (std::size_t i = 0; i < local.size(); ++i) {
                const glm::dmat3 linear(skinned.empty() ? world : skinned[i]);
                const bool flips = skinned.empty() ? mirrored : glm::determinant(linear) < 0.0;
                glm::dvec3 t = tangents.empty() ? glm::dvec3(0.0) : linear * glm::dvec3(tangents[i]);
                const double length = glm::length(t);
                const bool usable = !tangents.empty() && length > 1e-12 && std::isfinite(length) && tangents[i].w != 0.0;
                const float sign = (tangents.empty() || tangents[i].w >= 0.0) != flips ? 1.0f : -1.0f;
                surface.tangents.push_back(usable ? glm::vec4(glm::vec3(t / length), sign) : glm::vec4(0.0f));
            }
        }
        for (std::size_t i = 0; i < local.size(); ++i) {
            const glm::dvec3 p((skinned.empty() ? world : skinned[i]) * glm::dvec4(local[i], 1.0));
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
                throw FileError(path_, "vertex " + std::to_string(i) + " of " + what +
                                           " is not finite in world space (its transform overflows)");
            building.world.push_back(p);
        }
        for (auto triangle : assembleTriangles(mode, index)) {
            // glTF: a negative determinant flips the winding (under a skin, its corners' mean's)
            const bool flips =
                skinned.empty() ? mirrored
                                : glm::determinant(glm::dmat3(skinned[triangle[0]]) + glm::dmat3(skinned[triangle[1]]) +
                                                   glm::dmat3(skinned[triangle[2]])) < 0.0;
            if (flips) std::swap(triangle[1], triangle[2]);
            for (auto& v : triangle) v += base;
            surface.triangles.push_back(triangle);
            surface.triangleMaterial.push_back(material);
        }
    }

    void addCamera(const tinygltf::Node& node, const PlacedNode& placed) {
        if (node.camera >= static_cast<int>(model_.cameras.size()))
            throw FileError(path_, "node " + std::to_string(placed.index) + " uses camera " + std::to_string(node.camera) +
                                       ", which does not exist");
        const tinygltf::Camera& source = model_.cameras[static_cast<std::size_t>(node.camera)];
        Camera camera;
        camera.name = !source.name.empty() ? source.name
                                           : (!node.name.empty() ? node.name : "camera" + std::to_string(node.camera));
        const glm::dvec3 world(placed.world[3]);
        glm::dmat3 basis(placed.world);
        for (int c = 0; c < 3; ++c) {
            const double length = glm::length(basis[c]);
            if (length < 1e-12) {
                scene_.warnings.push_back("camera '" + camera.name + "' has a degenerate transform and is ignored");
                return;
            }
            basis[c] /= length;
        }
        camera.orientation = glm::mat3(basis);
        if (source.type == "orthographic") {
            camera.projection = Camera::Projection::Orthographic;
            camera.xmag = static_cast<float>(std::fabs(source.orthographic.xmag));
            camera.ymag = static_cast<float>(std::fabs(source.orthographic.ymag));
            camera.znear = static_cast<float>(source.orthographic.znear);
        } else {
            camera.yfov = static_cast<float>(source.perspective.yfov);
            camera.aspectRatio = static_cast<float>(source.perspective.aspectRatio);
            camera.znear = static_cast<float>(source.perspective.znear);
            if (!(camera.yfov > 0.0f && camera.yfov < 3.14159f)) {
                scene_.warnings.push_back("camera '" + camera.name + "' has an invalid field of view and is ignored");
                return;
            }
        }
        cameras_.emplace_back(camera, world);
    }

    const tinygltf::Model& model_;
    const std::string& path_;
    Scene& scene_;
    std::vector<WorldSurface> building_;
    std::vector<std::pair<Camera, glm::dvec3>> cameras_;  // with world positions, placed in finish()
    GltfLights lights_;
    GltfTextures textures_;
    std::vector<Light> placedLights_;  // positions in world coordinates until finish()
    std::set<std::string> usedNames_;
    int defaultMaterial_ = -1;
    std::size_t skippedPrimitives_ = 0;
    std::unordered_map<int, glm::dmat4> nodeWorld_;  // the placed nodes' (knowPlacements)
};

}  // namespace

Scene loadGltf(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) throw FileError(path, "no such file");
    if (!std::filesystem::is_regular_file(path, ec)) throw FileError(path, "not a regular file");
    constexpr std::uintmax_t kLargest = std::uintmax_t{1} << 32;  // glTF's own limit on a .glb
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec) throw FileError(path, "cannot read its size: " + ec.message());
    if (size > kLargest) throw FileError(path, "is larger than 4 GiB, the most a glTF file can be");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw FileError(path, "cannot be opened for reading");
    std::string bytes(static_cast<std::size_t>(size), '\0');
    in.read(bytes.data(), static_cast<std::streamsize>(size));
    if (static_cast<std::uintmax_t>(in.gcount()) != size) throw FileError(path, "could not be read whole");
    return loadGltfFromMemory(path, bytes);
}

Scene loadGltfFromMemory(const std::string& path, const std::string& bytes) {
    Scene scene;
    scene.path = path;
    scene.files = {path};
    const tinygltf::Model model = parse(path, bytes, scene.warnings);
    checkExtensions(model, path, scene.warnings);
    SceneBuilder builder(model, path, scene);
    builder.addMaterials();
    const std::vector<PlacedNode> nodes = placeNodes(model, path);
    if (nodes.empty()) throw FileError(path, "the scene is empty: it lists no nodes");
    builder.knowPlacements(nodes);
    for (const PlacedNode& placed : nodes) builder.addNode(placed);
    builder.finish();
    return scene;
}

}  // namespace rad
