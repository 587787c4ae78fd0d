#pragma once
// One OpenCL context for all device tests in a binary (program builds are cached in it), and a
// scene prepared up to its device buffers.

#include <memory>
#include <string>

#include "bvh/wide_bvh.h"
#include "cl/compute_context.h"
#include "prepared/device_scene.h"
#include "mesh/elements.h"
#include "mesh/mesh.h"
#include "scene/gltf_loader.h"
#include "test_support.h"

namespace rad::test {

inline ComputeContext& sharedCompute() {
    static std::shared_ptr<ComputeContext> compute = ComputeContext::open("");
    return *compute;
}

struct PreparedScene {
    Scene scene;
    Mesh mesh;
    WideBvh bvh;
    std::unique_ptr<DeviceScene> device;
    ElementMesh elements;  // one element per patch

    explicit PreparedScene(const std::string& relativePath, double patchSize = 0.0)
        : scene(loadGltf(sourcePath(relativePath))),
          mesh(buildMesh(scene, {patchSize, 10'000'000})),
          bvh(buildWideBvh(mesh.faces)),
          device(std::make_unique<DeviceScene>(sharedCompute(), mesh, bvh)),
          elements(ElementMesh::uniform(mesh, 0.0)) {}

    std::size_t surface(const std::string& name) const {
        for (std::size_t s = 0; s < mesh.surfaces.size(); ++s)
            if (mesh.surfaces[s].name == name) return s;
        throw std::runtime_error("no surface " + name);
    }
};

}  // namespace rad::test
