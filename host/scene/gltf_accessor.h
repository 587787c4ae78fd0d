#pragma once
// Reads glTF accessors with every range checked: buffer views inside their buffers,
// elements inside their views, sparse substitutions inside the accessor. tinygltf parses
// the JSON; it does not promise any of these, and files from other tools break them.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace tinygltf {
class Model;
}

namespace rad {

// Every accessor read names itself in errors through this context ("POSITION of mesh 'box'
// primitive 0"); the caller wraps InputError into a FileError for the scene's path.
struct AccessorRequest {
    int accessor = -1;
    std::string purpose;
};

// Positions: VEC3 of float, or of (normalized) integers as KHR_mesh_quantization allows.
// Values are returned as read, in double, and are checked to be finite.
std::vector<glm::dvec3> readPositions(const tinygltf::Model& model, const AccessorRequest& request);

// Texture coordinates: VEC2 of float, or of (normalized) byte or short as glTF and
// KHR_mesh_quantization allow.
// NORMAL: float, or (KHR_mesh_quantization) normalized signed byte or short; each finite (the
// caller normalises them after the node's transform, and decides about zero ones).
std::vector<glm::dvec3> readNormals(const tinygltf::Model& model, const AccessorRequest& request);
std::vector<glm::dvec2> readTexCoords(const tinygltf::Model& model, const AccessorRequest& request);
// TANGENT: VEC4 (xyz the tangent, w the bitangent's sign), float or (KHR_mesh_quantization)
// normalized signed byte or short; each finite (the caller decides about zero or bad ones).
std::vector<glm::dvec4> readTangents(const tinygltf::Model& model, const AccessorRequest& request);

// COLOR_0: VEC3 or VEC4 (its alpha is not returned) of float, or of normalized unsigned byte or
// short, as glTF allows; linear RGB, each component finite and clamped to [0, 1].
std::vector<glm::dvec3> readColors(const tinygltf::Model& model, const AccessorRequest& request);

// JOINTS_n: VEC4 of unsigned byte or short (not normalized), each a joint's place in the skin's list.
std::vector<std::array<std::uint32_t, 4>> readJoints(const tinygltf::Model& model, const AccessorRequest& request);
// WEIGHTS_n: VEC4 of float, or of normalized unsigned byte or short; each finite and not below
// zero (a float's rounding below zero, to -1e-6, is taken as zero).
std::vector<glm::dvec4> readWeights(const tinygltf::Model& model, const AccessorRequest& request);
// A skin's inverseBindMatrices: MAT4 of float, column by column; each finite.
std::vector<glm::dmat4> readMatrices(const tinygltf::Model& model, const AccessorRequest& request);

// Vertex indices: SCALAR of unsigned byte, short or int.
std::vector<std::uint32_t> readIndices(const tinygltf::Model& model, const AccessorRequest& request);

}  // namespace rad
