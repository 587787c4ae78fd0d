#include "io/baked_gltf.h"

#include <cstring>
#include <sstream>

#include <tiny_gltf.h>

#include "io/atomic_file.h"
#include "util/error.h"

namespace rad {
namespace {

// Appends raw bytes to the buffer (4-byte aligned) and returns a view over them.
int addView(tinygltf::Model& model, const void* data, std::size_t bytes, int target) {
    std::vector<unsigned char>& buffer = model.buffers[0].data;
    while (buffer.size() % 4 != 0) buffer.push_back(0);
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = buffer.size();
    view.byteLength = bytes;
    view.target = target;
    const auto* p = static_cast<const unsigned char*>(data);
    buffer.insert(buffer.end(), p, p + bytes);
    model.bufferViews.push_back(view);
    return static_cast<int>(model.bufferViews.size() - 1);
}

int addAccessor(tinygltf::Model& model, int view, int componentType, int type, std::size_t count,
                std::vector<double> min = {}, std::vector<double> max = {}) {
    tinygltf::Accessor a;
    a.bufferView = view;
    a.componentType = componentType;
    a.type = type;
    a.count = count;
    a.minValues = std::move(min);
    a.maxValues = std::move(max);
    model.accessors.push_back(a);
    return static_cast<int>(model.accessors.size() - 1);
}

// One surface side: its vertices (renumbered from 0), their radiance, and its triangles.
void addSide(tinygltf::Model& model, const Mesh& mesh, std::size_t side, const MeshVertices& vertices,
             const std::vector<glm::vec3>& radiance) {
    const MeshSurface& surface = mesh.surfaces[side];
    std::vector<std::uint32_t> local(vertices.positions.size(), 0xFFFFFFFFu);
    std::vector<float> positions, colours;
    std::vector<std::uint32_t> indices;
    std::vector<double> lo(3, 1e300), hi(3, -1e300);
    for (std::uint32_t k = 0; k < surface.patchCount; ++k)
        for (std::uint32_t v : vertices.patchCorners[surface.firstPatch + k]) {
            if (local[v] == 0xFFFFFFFFu) {
                local[v] = static_cast<std::uint32_t>(positions.size() / 3);
                for (int c = 0; c < 3; ++c) {
                    positions.push_back(vertices.positions[v][c]);
                    colours.push_back(radiance[v][c]);
                    lo[c] = std::min(lo[c], static_cast<double>(vertices.positions[v][c]));
                    hi[c] = std::max(hi[c], static_cast<double>(vertices.positions[v][c]));
                }
            }
            indices.push_back(local[v]);
        }
    const std::size_t count = positions.size() / 3;
    tinygltf::Primitive primitive;
    primitive.mode = TINYGLTF_MODE_TRIANGLES;
    primitive.material = 0;
    primitive.attributes["POSITION"] =
        addAccessor(model, addView(model, positions.data(), positions.size() * 4, TINYGLTF_TARGET_ARRAY_BUFFER),
                    TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, count, lo, hi);
    primitive.attributes["COLOR_0"] =
        addAccessor(model, addView(model, colours.data(), colours.size() * 4, TINYGLTF_TARGET_ARRAY_BUFFER),
                    TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, count);
    primitive.indices =
        addAccessor(model, addView(model, indices.data(), indices.size() * 4, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER),
                    TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR, indices.size());
    tinygltf::Mesh gltfMesh;
    gltfMesh.name = surface.name;
    gltfMesh.primitives.push_back(primitive);
    model.meshes.push_back(gltfMesh);
    tinygltf::Node node;
    node.name = surface.name;
    node.mesh = static_cast<int>(model.meshes.size() - 1);
    model.nodes.push_back(node);
    model.nodes[0].children.push_back(static_cast<int>(model.nodes.size() - 1));
}

}  // namespace

void writeBakedGltf(const std::string& path, const Mesh& mesh, const MeshVertices& vertices,
                    const std::vector<glm::vec3>& vertexRadiance, const glm::dvec3& origin) {
    tinygltf::Model model;
    model.asset.version = "2.0";
    model.asset.generator = "radiosity (baked lighting: linear radiance in COLOR_0)";
    model.buffers.resize(1);
    model.scenes.resize(1);
    model.defaultScene = 0;
    tinygltf::Material unlit;
    unlit.name = "baked";
    unlit.pbrMetallicRoughness.baseColorFactor = {1.0, 1.0, 1.0, 1.0};
    unlit.pbrMetallicRoughness.metallicFactor = 0.0;
    unlit.extensions["KHR_materials_unlit"] = tinygltf::Value(tinygltf::Value::Object());
    model.materials.push_back(unlit);
    model.extensionsUsed.push_back("KHR_materials_unlit");
    tinygltf::Node root;
    root.name = "scene";
    if (origin != glm::dvec3(0.0)) root.translation = {origin.x, origin.y, origin.z};
    model.nodes.push_back(root);
    model.scenes[0].nodes.push_back(0);
    for (std::size_t side = 0; side < mesh.surfaces.size(); ++side) addSide(model, mesh, side, vertices, vertexRadiance);

    std::ostringstream bytes;
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToStream(&model, bytes, false, true))
        throw RuntimeFailure(path + ": cannot encode the baked glTF");
    const std::string data = bytes.str();
    writeFileAtomically(path, [&](std::ostream& out) { out.write(data.data(), static_cast<std::streamsize>(data.size())); });
}

}  // namespace rad
