#include "io/gltf_buffers.h"

#include <string>

#include <stb_image_write.h>

#include "util/error.h"

namespace rad {

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
