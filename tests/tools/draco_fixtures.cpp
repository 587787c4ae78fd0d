// Writes Draco-compressed glTF files for tests/cli/draco.sh, with libdraco's own encoder: the
// same two quads plain (plain.glb), compressed without quantization (draco.glb: the same floats,
// the same order of triangles), with 11-bit positions (draco-11bit.glb), naming an attribute id
// the compressed mesh lacks (draco-bad-attribute.glb) and with the compressed bytes cut to half
// (draco-corrupt.glb), and the quads with vertex colours plain and compressed (plain-coloured.glb,
// draco-coloured.glb). A program of its own: libdraco.a carries its own copy of tinygltf, which
// must not share a program with the loader's.
// Usage: draco_fixtures DIR

#include <array>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <memory>
#include <string>
#include <stdexcept>
#include <vector>

#include <draco/compression/encode.h>
#include <draco/mesh/triangle_soup_mesh_builder.h>

namespace {

// Two quads facing each other (a floor and a ceiling lamp), as float triangles.
std::vector<std::array<float, 9>> quads() {
    const float y0 = 0.013f, y1 = 0.93f;
    return {{0.1f, y0, 0.2f, 0.1f, y0, 1.3f, 1.7f, y0, 1.3f}, {0.1f, y0, 0.2f, 1.7f, y0, 1.3f, 1.7f, y0, 0.2f},
            {0.4f, y1, 0.5f, 1.2f, y1, 0.5f, 1.2f, y1, 1.1f}, {0.4f, y1, 0.5f, 1.2f, y1, 1.1f, 0.4f, y1, 1.1f}};
}

// A .glb of the JSON text and the binary chunk.
std::string glb(std::string json, std::string bin) {
    json.append((4 - json.size() % 4) % 4, ' ');
    bin.append((4 - bin.size() % 4) % 4, '\0');
    std::string out;
    auto u32 = [&out](std::uint32_t v) { out.append(reinterpret_cast<const char*>(&v), 4); };
    u32(0x46546C67);
    u32(2);
    u32(static_cast<std::uint32_t>(12 + 8 + json.size() + 8 + bin.size()));
    u32(static_cast<std::uint32_t>(json.size()));
    u32(0x4E4F534A);
    out += json;
    u32(static_cast<std::uint32_t>(bin.size()));
    u32(0x004E4942);
    out += bin;
    return out;
}

std::string head(std::size_t binLength) {
    return R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"name":"quads","mesh":0}],)"
           R"("buffers":[{"byteLength":)" + std::to_string(binLength) + "}],";
}

// COLOR_0 of the quads' twelve corners (coloured files) as bytes: the floor's reddish, the lamp's
// bluish. The compressed file holds the bytes without Draco's "normalized" flag, as many encoders
// write them; the plain one the floats they stand for.
std::vector<std::array<std::uint8_t, 3>> colourBytes() {
    std::vector<std::array<std::uint8_t, 3>> out;
    for (int v = 0; v < 12; ++v)
        out.push_back(v < 6 ? std::array<std::uint8_t, 3>{230, 64, 32} : std::array<std::uint8_t, 3>{32, 64, 230});
    return out;
}

std::vector<std::array<float, 3>> colours() {
    std::vector<std::array<float, 3>> out;
    for (const auto& c : colourBytes()) out.push_back({c[0] / 255.0f, c[1] / 255.0f, c[2] / 255.0f});
    return out;
}

// The quads as a plain triangle list (with `coloured`, their COLOR_0 too).
std::string plainGlb(bool coloured = false) {
    std::string bin;
    for (const auto& t : quads()) bin.append(reinterpret_cast<const char*>(t.data()), sizeof t);
    const std::size_t positions = bin.size();
    if (coloured)
        for (const auto& c : colours()) bin.append(reinterpret_cast<const char*>(c.data()), sizeof c);
    const std::string json =
        head(bin.size()) + R"("bufferViews":[{"buffer":0,"byteLength":)" + std::to_string(positions) + "}" +
        (coloured ? R"(,{"buffer":0,"byteOffset":)" + std::to_string(positions) + R"(,"byteLength":144})" : "") +
        "]," + R"("accessors":[{"bufferView":0,"componentType":5126,"count":12,"type":"VEC3",)"
        R"("min":[0.1,0.013,0.2],"max":[1.7,0.93,1.3]})" +
        (coloured ? R"(,{"bufferView":1,"componentType":5126,"count":12,"type":"VEC3"})" : "") + "]," +
        R"("meshes":[{"primitives":[{"attributes":{"POSITION":0)" + (coloured ? R"(,"COLOR_0":1)" : "") + "}}]}]}";
    return glb(json, bin);
}

// The same quads through libdraco's encoder; `bits` 0 keeps the floats as they are.
std::string dracoGlb(int bits, int attributeId = -1, bool corrupt = false, bool coloured = false) {
    draco::TriangleSoupMeshBuilder builder;
    const auto triangles = quads();
    builder.Start(static_cast<int>(triangles.size()));
    const int position = builder.AddAttribute(draco::GeometryAttribute::POSITION, 3, draco::DT_FLOAT32);
    const int colour = coloured ? builder.AddAttribute(draco::GeometryAttribute::COLOR, 3, draco::DT_UINT8) : -1;
    const auto c = colourBytes();
    for (std::size_t f = 0; f < triangles.size(); ++f) {
        builder.SetAttributeValuesForFace(position, draco::FaceIndex(static_cast<std::uint32_t>(f)), &triangles[f][0],
                                          &triangles[f][3], &triangles[f][6]);
        if (coloured)
            builder.SetAttributeValuesForFace(colour, draco::FaceIndex(static_cast<std::uint32_t>(f)), c[3 * f].data(),
                                              c[3 * f + 1].data(), c[3 * f + 2].data());
    }
    const std::unique_ptr<draco::Mesh> mesh = builder.Finalize();
    draco::Encoder encoder;
    encoder.SetEncodingMethod(draco::MESH_SEQUENTIAL_ENCODING);  // keeps the triangles' order
    if (bits > 0) encoder.SetAttributeQuantization(draco::GeometryAttribute::POSITION, bits);
    draco::EncoderBuffer encoded;
    if (!encoder.EncodeMeshToBuffer(*mesh, &encoded).ok()) throw std::runtime_error("draco cannot encode");
    std::string bin(encoded.data(), encoded.size());
    if (corrupt) bin.resize(bin.size() / 2);  // Draco has no checksum: cut short, it cannot decode
    const int id = attributeId >= 0 ? attributeId : static_cast<int>(mesh->attribute(position)->unique_id());
    const std::string colourId = coloured ? std::to_string(mesh->attribute(colour)->unique_id()) : "";
    const std::string json =
        head(bin.size()) +
        R"("extensionsUsed":["KHR_draco_mesh_compression"],"extensionsRequired":["KHR_draco_mesh_compression"],)"
        R"("bufferViews":[{"buffer":0,"byteLength":)" + std::to_string(bin.size()) + "}]," +
        R"("accessors":[{"componentType":5126,"count":)" + std::to_string(mesh->num_points()) +
        R"(,"type":"VEC3","min":[0.1,0.013,0.2],"max":[1.7,0.93,1.3]},)"
        R"({"componentType":5125,"count":)" + std::to_string(3 * triangles.size()) + R"(,"type":"SCALAR"})" +
        (coloured ? R"(,{"componentType":5126,"count":)" + std::to_string(mesh->num_points()) + R"(,"type":"VEC3"})"
                  : "") +
        "]," + R"("meshes":[{"primitives":[{"attributes":{"POSITION":0)" + (coloured ? R"(,"COLOR_0":2)" : "") +
        R"(},"indices":1,"extensions":)"
        R"({"KHR_draco_mesh_compression":{"bufferView":0,"attributes":{"POSITION":)" + std::to_string(id) +
        (coloured ? R"(,"COLOR_0":)" + colourId : "") + "}}}}]}]}";
    return glb(json, bin);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: draco_fixtures DIR\n");
        return 2;
    }
    const std::string dir = argv[1];
    const std::pair<const char*, std::string> files[] = {{"plain.glb", plainGlb()},
                                                         {"draco.glb", dracoGlb(0)},
                                                         {"draco-11bit.glb", dracoGlb(11)},
                                                         {"draco-bad-attribute.glb", dracoGlb(0, 77)},
                                                         {"draco-corrupt.glb", dracoGlb(0, -1, true)},
                                                         {"plain-coloured.glb", plainGlb(true)},
                                                         {"draco-coloured.glb", dracoGlb(0, -1, false, true)}};
    for (const auto& [name, bytes] : files) {
        std::ofstream out(dir + "/" + name, std::ios::binary);
        out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        if (!out) {
            std::fprintf(stderr, "draco_fixtures: cannot write %s/%s\n", dir.c_str(), name);
            return 1;
        }
    }
    return 0;
}
