// libFuzzer target over the path from glTF bytes to patches: preflight, the glTF parser, the
// scene builder, meshing, the BVH and vertex welding. Every input must end in a scene or in a
// rad::Error; a crash, a sanitizer report, a hang or a huge allocation is a bug. Inputs that
// found bugs stay in tests/fuzz/found/ as regression tests.
//
// Build with clang: cmake -DRADIOSITY_FUZZ=ON -DRADIOSITY_SANITIZE=ON (tests/sanitize/run.sh).

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "bvh/wide_bvh.h"
#include "mesh/mesh.h"
#include "mesh/vertices.h"
#include "scene/gltf_loader.h"
#include "util/error.h"

namespace {

// An empty directory for the scene "file", so external URIs find nothing to read.
const std::string& sceneDirectory() {
    static const std::string directory = [] {
        std::filesystem::path p = std::filesystem::temp_directory_path() / "radiosity-fuzz-empty";
        std::filesystem::create_directories(p);
        return p.string();
    }();
    return directory;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    const bool binary = size >= 4 && bytes.compare(0, 4, "glTF") == 0;
    const std::string path = sceneDirectory() + (binary ? "/input.glb" : "/input.gltf");
    try {
        const rad::Scene scene = rad::loadGltfFromMemory(path, bytes);
        rad::MeshOptions options;
        options.maxPatches = 20000;  // keeps each input fast; larger meshes are refused cleanly
        const rad::Mesh mesh = rad::buildMesh(scene, options);
        const rad::WideBvh bvh = rad::buildWideBvh(mesh.faces);
        const rad::MeshVertices vertices = rad::weldVertices(mesh);
        if (vertices.patchCorners.size() != mesh.patches.size() || bvh.nodes.empty()) std::abort();
    } catch (const rad::Error&) {
        // A clear refusal is a correct answer.
    }
    return 0;
}
