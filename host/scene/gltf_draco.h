#pragma once
// KHR_draco_mesh_compression: a primitive whose vertices and triangles are one Draco-compressed
// buffer view. Decoded here with Debian's libdraco, every index and attribute id checked (the
// file names them; a wrong one must be an error, not a read out of bounds).

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/ext/vector_double2.hpp>
#include <glm/ext/vector_double3.hpp>

namespace tinygltf {
class Model;
struct Primitive;
}  // namespace tinygltf

namespace rad {

// The vertex data of a primitive as the loader takes it. An attribute the extension does not
// compress is left empty here: the loader reads it from its accessor as usual.
struct DecodedPrimitive {
    std::vector<glm::dvec3> positions;
    std::vector<glm::dvec3> normals;
    std::array<std::vector<glm::dvec2>, 2> texCoords;  // TEXCOORD_0, TEXCOORD_1
    std::vector<glm::dvec3> colors;                    // COLOR_0 (rgb, clamped to [0, 1]; alpha dropped)
    std::vector<std::uint32_t> triangles;              // a triangle list, three indices a triangle
};

bool isDracoCompressed(const tinygltf::Primitive& primitive);

// The file's bytes (a .gltf's JSON, or a whole .glb) with the `indices` of every compressed
// primitive taken out. tinygltf, built without Draco, refuses an indices accessor without a
// buffer view ("accessor[1] invalid bufferView"), which is how the extension writes it; the
// triangles come from the compressed data anyway. Bytes it cannot parse are returned as they are,
// for the parser to report.
std::string withoutCompressedIndices(const std::string& bytes, bool binary);

// Throws InputError naming `what` ("mesh 'engine' primitive 0") for a bad buffer view, an
// attribute id the compressed mesh lacks, or data Draco cannot decode.
DecodedPrimitive decodeDracoPrimitive(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                                      const std::string& what);

}  // namespace rad
