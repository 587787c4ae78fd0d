#pragma once
// Checks on a glTF file's JSON before the glTF parser sees it:
// - types: the properties the loader relies on have the types the glTF 2.0 schema gives them
//   (tinygltf silently ignores some that do not, e.g. a node's `children` as an object);
// - external files: only relative URIs that stay in the scene's own directory are followed; an
//   absolute URI, a scheme (http:, file:), or a path that climbs out with ".." is refused by
//   name, before anything is read.
// Unparseable JSON is left for the glTF parser to report.

#include <string>

namespace tinygltf {
struct FsCallbacks;
}

namespace rad {

// Throws FileError naming the first property that is wrong. `binary`: the file is a .glb (its
// JSON is the first chunk; the header has been checked).
void preflightGltf(const std::string& path, const std::string& bytes, bool binary);

// File-system callbacks for tinygltf that find files only inside `directory` (tinygltf would
// otherwise also look in the working directory). `directory` must outlive the parse.
tinygltf::FsCallbacks confinedFileSystem(const std::string& directory);

}  // namespace rad
