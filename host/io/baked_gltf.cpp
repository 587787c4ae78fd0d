#include "io/baked_gltf.h"

#include <algorithm>
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
class SideBuilder {
public:
    SideBuilder(const MeshVertices& vertices, const std::vector<glm::vec3>& radiance)
        : vertices_(vertices), radiance_(radiance), local_(vertices.positions.size(), 0xFFFFFFFFu) {}

    std::uint32_t vertex(std::uint32_t v) {
        if (local_[v] == 0xFFFFFFFFu) local_[v] = add(vertices_.positions[v], radiance_[v]);
        return local_[v];
    }

    std::uint32_t add(const glm::vec3& position, const glm::vec3& value) {
        for (int c = 0; c < 3; ++c) {
            positions.push_back(position[c]);
            colours.push_back(value[c]);
            lo[c] = std::min(lo[c], static_cast<double>(position[c]));
            hi[c] = std::max(hi[c], static_cast<double>(position[c]));
        }
        return static_cast<std::uint32_t>(positions.size() / 3 - 1);
    }

    // An element's triangle; with T-vertices on its edges, a fan around its centroid, whose
    // value is the mean of its corners' (what linear interpolation gives there).
    void element(std::size_t e) {
        const auto& c = vertices_.corners[e];
        const auto& points = vertices_.edgePoints[e];
        if (points[0].empty() && points[1].empty() && points[2].empty()) {
            for (std::uint32_t v : c) indices.push_back(vertex(v));
            return;
        }
        std::vector<std::uint32_t> ring;
        for (int k = 0; k < 3; ++k) {
            ring.push_back(vertex(c[k]));
            for (std::uint32_t v : points[k]) ring.push_back(vertex(v));
        }
        const glm::vec3 centre = (vertices_.positions[c[0]] + vertices_.positions[c[1]] + vertices_.positions[c[2]]) / 3.0f;
        const glm::vec3 value = (radiance_[c[0]] + radiance_[c[1]] + radiance_[c[2]]) / 3.0f;
        const std::uint32_t middle = add(centre, value);
        for (std::size_t k = 0; k < ring.size(); ++k) indices.insert(indices.end(), {middle, ring[k], ring[(k + 1) % ring.size()]});
    }

    std::vector<float> positions, colours;
    std::vector<std::uint32_t> indices;
    std::vector<double> lo = std::vector<double>(3, 1e300), hi = std::vector<double>(3, -1e300);

private:
    const MeshVertices& vertices_;
    const std::vector<glm::vec3>& radiance_;
    std::vector<std::uint32_t> local_;
};

void addSide(tinygltf::Model& model, const Mesh& mesh, std::size_t side, const ElementMesh& elements,
             const MeshVertices& vertices, const std::vector<glm::vec3>& radiance) {
    const MeshSurface& surface = mesh.surfaces[side];
    SideBuilder b(vertices, radiance);
    for (std::uint32_t k = 0; k < surface.patchCount; ++k) {
        const std::uint32_t patch = surface.firstPatch + k;
        for (std::uint32_t e = elements.elementStart()[patch]; e < elements.elementStart()[patch + 1]; ++e) b.element(e);
    }
    const std::size_t count = b.positions.size() / 3;
    tinygltf::Primitive primitive;
    primitive.mode = TINYGLTF_MODE_TRIANGLES;
    primitive.material = 0;
    primitive.attributes["POSITION"] =
        addAccessor(model, addView(model, b.positions.data(), b.positions.size() * 4, TINYGLTF_TARGET_ARRAY_BUFFER),
                    TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, count, b.lo, b.hi);
    primitive.attributes["COLOR_0"] =
        addAccessor(model, addView(model, b.colours.data(), b.colours.size() * 4, TINYGLTF_TARGET_ARRAY_BUFFER),
                    TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, count);
    primitive.indices =
        addAccessor(model, addView(model, b.indices.data(), b.indices.size() * 4, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER),
                    TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR, b.indices.size());
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

void writeBakedGltf(const std::string& path, const Mesh& mesh, const ElementMesh& elements, const MeshVertices& vertices,
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
    for (std::size_t side = 0; side < mesh.surfaces.size(); ++side)
        addSide(model, mesh, side, elements, vertices, vertexRadiance);

    std::ostringstream bytes;
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToStream(&model, bytes, false, true))
        throw RuntimeFailure(path + ": cannot encode the baked glTF");
    const std::string data = bytes.str();
    writeFileAtomically(path, [&](std::ostream& out) { out.write(data.data(), static_cast<std::streamsize>(data.size())); });
}

}  // namespace rad
