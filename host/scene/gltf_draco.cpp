#include "scene/gltf_draco.h"

#include <cmath>

#include <draco/compression/decode.h>
#include <glm/common.hpp>
#include <glm/ext/vector_double4.hpp>
#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>
#include <draco/core/decoder_buffer.h>
#include <tiny_gltf.h>

#include "scene/gltf_json_edit.h"
#include "util/error.h"

namespace rad {
namespace {

constexpr const char* kExtension = "KHR_draco_mesh_compression";

// `prefix` is where the object lies in the extension ("attributes."), for messages.
int integer(const tinygltf::Value& object, const char* key, const std::string& what, const char* prefix = "") {
    if (!object.Has(key) || !object.Get(key).IsNumber())
        throw InputError(what + ": " + kExtension + "." + prefix + key + " must be an index");
    const double value = object.Get(key).GetNumberAsDouble();
    if (!(value >= 0.0) || value > 2147483647.0 || value != std::floor(value))
        throw InputError(what + ": " + kExtension + "." + prefix + key + " must be an index");
    return static_cast<int>(value);
}

// The attribute `name` of the compressed mesh, or null where the extension does not list it.
const draco::PointAttribute* attribute(const draco::Mesh& mesh, const tinygltf::Value& attributes,
                                       const std::string& name, const std::string& what) {
    if (!attributes.Has(name)) return nullptr;
    const int id = integer(attributes, name.c_str(), what, "attributes.");
    const draco::PointAttribute* found = mesh.GetAttributeByUniqueId(static_cast<std::uint32_t>(id));
    if (!found)
        throw InputError(what + ": " + kExtension + " names attribute " + std::to_string(id) + " for " + name +
                         ", which the compressed mesh does not hold");
    return found;
}

template <int N>
std::vector<glm::vec<N, double>> values(const draco::Mesh& mesh, const draco::PointAttribute& source,
                                        const std::string& name, const std::string& what) {
    if (source.num_components() != N)
        throw InputError(what + ": the compressed " + name + " has " + std::to_string(source.num_components()) +
                         " components, not " + std::to_string(N));
    std::vector<glm::vec<N, double>> out(mesh.num_points());
    float value[N];
    for (draco::PointIndex i(0); i < mesh.num_points(); ++i) {
        if (!source.ConvertValue<float>(source.mapped_index(i), N, value))
            throw InputError(what + ": the compressed " + name + " cannot be read as numbers");
        for (int c = 0; c < N; ++c) {
            if (!std::isfinite(value[c])) throw InputError(what + ": the compressed " + name + " is not finite");
            out[i.value()][c] = value[c];
        }
    }
    return out;
}

}  // namespace

std::string withoutCompressedIndices(const std::string& bytes, bool binary) {
    return editGltfJson(bytes, binary, [](nlohmann::json& doc) {
        if (!doc.contains("meshes") || !doc["meshes"].is_array()) return false;
        bool changed = false;
        for (auto& mesh : doc["meshes"]) {
            if (!mesh.is_object() || !mesh.contains("primitives") || !mesh["primitives"].is_array()) continue;
            for (auto& primitive : mesh["primitives"]) {
                if (!primitive.is_object() || !primitive.contains("indices") || !primitive.contains("extensions"))
                    continue;
                const auto& extensions = primitive["extensions"];
                if (!extensions.is_object() || !extensions.contains(kExtension)) continue;
                primitive.erase("indices");
                changed = true;
            }
        }
        return changed;
    });
}

bool isDracoCompressed(const tinygltf::Primitive& primitive) {
    return primitive.extensions.count(kExtension) > 0;
}

DecodedPrimitive decodeDracoPrimitive(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                                      const std::string& what) {
    const tinygltf::Value& extension = primitive.extensions.at(kExtension);
    if (!extension.IsObject()) throw InputError(what + ": " + kExtension + " must be an object");
    const int view = integer(extension, "bufferView", what);
    if (view >= static_cast<int>(model.bufferViews.size()))
        throw InputError(what + ": " + kExtension + " names buffer view " + std::to_string(view) + ", which does not exist");
    const tinygltf::BufferView& bufferView = model.bufferViews[static_cast<std::size_t>(view)];
    if (bufferView.buffer < 0 || bufferView.buffer >= static_cast<int>(model.buffers.size()))
        throw InputError(what + ": the compressed data's buffer view names a buffer that does not exist");
    const std::vector<unsigned char>& buffer = model.buffers[static_cast<std::size_t>(bufferView.buffer)].data;
    if (bufferView.byteOffset > buffer.size() || bufferView.byteLength > buffer.size() - bufferView.byteOffset)
        throw InputError(what + ": the compressed data's buffer view lies outside its buffer");
    if (!extension.Has("attributes") || !extension.Get("attributes").IsObject())
        throw InputError(what + ": " + kExtension + ".attributes must be an object");
    const tinygltf::Value& attributes = extension.Get("attributes");

    draco::DecoderBuffer data;
    data.Init(reinterpret_cast<const char*>(buffer.data() + bufferView.byteOffset), bufferView.byteLength);
    draco::Decoder decoder;
    auto decoded = decoder.DecodeMeshFromBuffer(&data);
    if (!decoded.ok())
        throw InputError(what + ": the Draco-compressed mesh cannot be decoded (" + decoded.status().error_msg_string() + ")");
    const std::unique_ptr<draco::Mesh> mesh = std::move(decoded).value();
    // What a few bytes may claim to hold: no more than glTF's own accessors may (2^28), nor more
    // than 64 vertices or triangles a compressed byte (Draco's best is a few bits a triangle).
    const double most = std::min(268435456.0, 64.0 * static_cast<double>(bufferView.byteLength));
    if (static_cast<double>(mesh->num_points()) > most || static_cast<double>(mesh->num_faces()) > most)
        throw InputError(what + ": the Draco-compressed mesh claims " + std::to_string(mesh->num_points()) +
                         " vertices and " + std::to_string(mesh->num_faces()) + " triangles in " +
                         std::to_string(bufferView.byteLength) + " bytes: absurdly many");

    DecodedPrimitive out;
    const draco::PointAttribute* position = attribute(*mesh, attributes, "POSITION", what);
    if (!position) throw InputError(what + ": " + kExtension + " does not compress POSITION");
    out.positions = values<3>(*mesh, *position, "POSITION", what);
    if (const draco::PointAttribute* normal = attribute(*mesh, attributes, "NORMAL", what))
        out.normals = values<3>(*mesh, *normal, "NORMAL", what);
    for (int set = 0; set < 2; ++set) {
        const std::string name = "TEXCOORD_" + std::to_string(set);
        if (const draco::PointAttribute* uv = attribute(*mesh, attributes, name, what))
            out.texCoords[static_cast<std::size_t>(set)] = values<2>(*mesh, *uv, name, what);
    }
    if (const draco::PointAttribute* colour = attribute(*mesh, attributes, "COLOR_0", what)) {
        if (colour->num_components() == 4)
            for (const glm::dvec4& c : values<4>(*mesh, *colour, "COLOR_0", what)) out.colors.emplace_back(c);
        else
            out.colors = values<3>(*mesh, *colour, "COLOR_0", what);
        // Draco scales integers to [0, 1] only where its own data says they are normalized, which
        // many encoders leave unsaid (the glTF accessor says it): integers are divided by their
        // type's largest value here, in float, as a normalized accessor reads.
        float largest = 1.0f;
        if (!colour->normalized()) switch (colour->data_type()) {
                case draco::DT_UINT8: largest = 255.0f; break;
                case draco::DT_UINT16: largest = 65535.0f; break;
                case draco::DT_UINT32: largest = 4294967295.0f; break;
                case draco::DT_INT8: largest = 127.0f; break;
                case draco::DT_INT16: largest = 32767.0f; break;
                case draco::DT_INT32: largest = 2147483647.0f; break;
                default: break;
            }
        for (glm::dvec3& c : out.colors) c = glm::clamp(glm::dvec3(glm::vec3(c) / largest), 0.0, 1.0);
    }
    out.triangles.reserve(3 * static_cast<std::size_t>(mesh->num_faces()));
    for (draco::FaceIndex f(0); f < mesh->num_faces(); ++f)
        for (int c = 0; c < 3; ++c) {
            const std::uint32_t v = mesh->face(f)[c].value();
            if (v >= mesh->num_points()) throw InputError(what + ": a compressed triangle names a vertex out of range");
            out.triangles.push_back(v);
        }
    return out;
}

}  // namespace rad
