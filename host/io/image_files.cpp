#include "io/image_files.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStdIO.h>
#include <stb_image_write.h>

#include "io/atomic_file.h"
#include "render/tone_map.h"
#include "util/error.h"

namespace rad {

void writeExr(const std::string& path, const Image& image) {
    std::string bytes;
    try {
        Imf::Header header(image.width, image.height);
        for (const char* channel : {"R", "G", "B"}) header.channels().insert(channel, Imf::Channel(Imf::FLOAT));
        Imf::FrameBuffer frame;
        char* base = const_cast<char*>(reinterpret_cast<const char*>(image.pixels.data()));
        const std::size_t xStride = sizeof(glm::vec3), yStride = xStride * static_cast<std::size_t>(image.width);
        frame.insert("R", Imf::Slice(Imf::FLOAT, base, xStride, yStride));
        frame.insert("G", Imf::Slice(Imf::FLOAT, base + sizeof(float), xStride, yStride));
        frame.insert("B", Imf::Slice(Imf::FLOAT, base + 2 * sizeof(float), xStride, yStride));
        Imf::StdOSStream stream;
        {
            Imf::OutputFile file(stream, header);
            file.setFrameBuffer(frame);
            file.writePixels(image.height);
        }
        bytes = stream.str();
    } catch (const std::exception& e) {
        throw RuntimeFailure(path + ": cannot encode the EXR image: " + e.what());
    }
    writeFileAtomically(path, [&](std::ostream& out) { out.write(bytes.data(), static_cast<std::streamsize>(bytes.size())); });
}

void writePngPreview(const std::string& path, const Image& image) {
    const std::vector<std::uint8_t> rgb = toneMapToSrgb(image);
    std::string bytes;
    const int ok = stbi_write_png_to_func(
        [](void* context, void* data, int size) { static_cast<std::string*>(context)->append(static_cast<char*>(data), size); },
        &bytes, image.width, image.height, 3, rgb.data(), image.width * 3);
    if (!ok) throw RuntimeFailure(path + ": cannot encode the PNG image");
    writeFileAtomically(path, [&](std::ostream& out) { out.write(bytes.data(), static_cast<std::streamsize>(bytes.size())); });
}

Image readExr(const std::string& path) {
    try {
        Imf::InputFile file(path.c_str());
        const Imath::Box2i window = file.header().dataWindow();
        Image image;
        image.width = window.max.x - window.min.x + 1;
        image.height = window.max.y - window.min.y + 1;
        image.pixels.resize(static_cast<std::size_t>(image.width) * image.height);
        char* base = reinterpret_cast<char*>(image.pixels.data()) -
                     (static_cast<std::ptrdiff_t>(window.min.y) * image.width + window.min.x) * sizeof(glm::vec3);
        const std::size_t xStride = sizeof(glm::vec3), yStride = xStride * static_cast<std::size_t>(image.width);
        Imf::FrameBuffer frame;
        frame.insert("R", Imf::Slice(Imf::FLOAT, base, xStride, yStride));
        frame.insert("G", Imf::Slice(Imf::FLOAT, base + sizeof(float), xStride, yStride));
        frame.insert("B", Imf::Slice(Imf::FLOAT, base + 2 * sizeof(float), xStride, yStride));
        file.setFrameBuffer(frame);
        file.readPixels(window.min.y, window.max.y);
        return image;
    } catch (const std::exception& e) {
        throw RuntimeFailure(path + ": cannot read the EXR image: " + e.what());
    }
}

}  // namespace rad
