// libFuzzer target over the path from glTF bytes to patches: preflight, the glTF parser, the
// scene builder, meshing, the BVH, element splitting and vertex welding. Every input must end in a scene or in a
// rad::Error; a crash, a sanitizer report, a hang or a huge allocation is a bug. Inputs that
// found bugs stay in tests/fuzz/found/ as regression tests.
//
// Build with clang: cmake -DRADIOSITY_FUZZ=ON -DRADIOSITY_SANITIZE=ON (tests/sanitize/run.sh).

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "bvh/wide_bvh.h"
#include "mesh/elements.h"
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
        // Elements one per patch, the first few split twice so T-vertices appear as they do
        // after adaptive refinement.
        rad::ElementMesh elements = rad::ElementMesh::uniform(mesh, 0.0);
        std::vector<std::uint32_t> children;
        const std::vector<std::uint32_t> first{0, 1, 2};
        std::vector<std::uint32_t> some;
        for (std::uint32_t e : first)
            if (e < elements.elements().size()) some.push_back(e);
        elements.split(some, 0.0, 4 * elements.elements().size(), &children);
        elements.split(children, 0.0, 4 * elements.elements().size());
        const rad::MeshVertices vertices = rad::weldVertices(mesh, elements);
        const std::vector<glm::vec3> values(elements.elements().size(), glm::vec3(1.0f));
        const std::vector<glm::vec3> atVertices = rad::vertexValues(elements, vertices, values);
        if (vertices.corners.size() != elements.elements().size() ||
            atVertices.size() != vertices.positions.size() || bvh.nodes.empty())
            std::abort();
    } catch (const rad::Error&) {
        // A clear refusal is a correct answer.
    }
    return 0;
}
