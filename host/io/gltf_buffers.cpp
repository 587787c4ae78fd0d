#include "io/gltf_buffers.h"

#include <sstream>
#include <string>
#include <utility>

#include <stb_image_write.h>

#include "io/atomic_file.h"
#include "util/error.h"

namespace rad {

tinygltf::Model startGlb(const std::string& generator, const glm::dvec3& origin) {
    tinygltf::Model model;
    model.asset.version = "2.0";
    model.asset.generator = generator;
    model.buffers.resize(1);
    model.scenes.resize(1);
    model.defaultScene = 0;
    tinygltf::Node root;
    root.name = "scene";
    if (origin != glm::dvec3(0.0)) root.translation = {origin.x, origin.y, origin.z};
    model.nodes.push_back(root);
    model.scenes[0].nodes.push_back(0);
    return model;
}

void writeGlb(const std::string& path, tinygltf::Model& model) {
    std::ostringstream bytes;
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToStream(&model, bytes, false, true))
        throw RuntimeFailure(path + ": cannot encode the glTF");
    const std::string data = bytes.str();
    writeFileAtomically(path,
                        [&](std::ostream& out) { out.write(data.data(), static_cast<std::streamsize>(data.size())); });
}

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
                std::vector<double> min, std::vector<double> max) {
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

void addSurfaceNode(tinygltf::Model& model, tinygltf::Mesh mesh, const std::string& name) {
    model.meshes.push_back(std::move(mesh));
    tinygltf::Node node;
    node.name = name;
    node.mesh = static_cast<int>(model.meshes.size() - 1);
    model.nodes.push_back(node);
    model.nodes[0].children.push_back(static_cast<int>(model.nodes.size() - 1));
}

int addPngImage(tinygltf::Model& model, const TextureImage& image) {
    std::string png;
    const int ok = stbi_write_png_to_func(
        [](void* context, void* data, int size) {
            static_cast<std::string*>(context)->append(static_cast<char*>(data), size);
        },
        &png, image.width, image.height, 4, image.rgba.data(), image.width * 4);
    if (!ok) throw RuntimeFailure("cannot encode the texture '" + image.name + "' as PNG for the baked glTF");
    tinygltf::Image out;
    out.name = image.name;
    out.mimeType = "image/png";
    out.bufferView = addView(model, png.data(), png.size(), 0);
    model.images.push_back(out);
    return static_cast<int>(model.images.size() - 1);
}

}  // namespace rad
