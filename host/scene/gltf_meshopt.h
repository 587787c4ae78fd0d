#pragma once
// EXT_meshopt_compression: buffer views whose bytes meshoptimizer's codecs compressed (vertex
// attributes, triangle lists, index sequences; the octahedral, quaternion and exponential
// filters), as gltfpack and glTF-Transform write them for the web. Decoded with Debian's
// libmeshoptimizer into buffers of their own before any accessor is read, every property
// checked against the extension's rules first (the file names sizes and offsets; a wrong one
// must be an error, not a read out of bounds).

#include <string>

namespace tinygltf {
class Model;
}

namespace rad {

// The file's bytes (a .gltf's JSON, or a whole .glb) with every placeholder buffer (one without
// a `uri`, referenced only by compressed buffer views: the extension's fallback buffers) given a
// data URI of four zero bytes. tinygltf refuses a buffer without a URI in a .gltf, and in a .glb would fill it
// with the binary chunk; its bytes are never read, since the compressed views are decoded from
// the buffers their extension names.
std::string withEmptyFallbackBuffers(const std::string& bytes, bool binary);

// Decodes every compressed buffer view of `model` into a new buffer and points the view at it,
// removing the extension from the view. Throws FileError naming `path`, the buffer view and the
// problem.
void decodeMeshoptBufferViews(tinygltf::Model& model, const std::string& path);

}  // namespace rad
