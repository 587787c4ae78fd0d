#pragma once
// One OpenCL context for all device tests in a binary (program builds are cached in it), and a
// scene prepared on it (prepared/prepared_scene.h) with one element per patch.

#include <memory>
#include <stdexcept>
#include <string>

#include "mesh/elements.h"
#include "prepared/prepared_scene.h"
#include "render/view.h"
#include "scene/gltf_loader.h"
#include "test_support.h"

namespace rad::test {

inline const std::shared_ptr<ComputeContext>& sharedComputeHandle() {
    static const std::shared_ptr<ComputeContext> compute = ComputeContext::open("");
    return compute;
}

inline ComputeContext& sharedCompute() {
    return *sharedComputeHandle();
}

struct TestScene : rad::PreparedScene {
    ElementMesh elements;  // one element per patch

    explicit TestScene(const std::string& relativePath, double patchSize = 0.0)
        : rad::PreparedScene(loadGltf(sourcePath(relativePath)), {patchSize, 10'000'000}, sharedComputeHandle()),
          elements(ElementMesh::uniform(mesh(), 0.0)) {}

    // A scene loaded and then changed (a sky, a light) before it is prepared.
    TestScene(Scene scene, double patchSize)
        : rad::PreparedScene(std::move(scene), {patchSize, 10'000'000}, sharedComputeHandle()),
          elements(ElementMesh::uniform(mesh(), 0.0)) {}

    std::size_t surface(const std::string& name) const {
        for (std::size_t s = 0; s < mesh().surfaces.size(); ++s)
            if (mesh().surfaces[s].name == name) return s;
        throw std::runtime_error("no surface " + name);
    }
};

// From the centre of a cube centred on the scene's origin, looking into a corner with a wide
// lens: every pixel sees a face (the furnaces' view).
inline View insideTheCube() {
    View v;
    v.position = glm::vec3(0.0f);
    v.forward = glm::normalize(glm::vec3(1.0f, 0.3f, 0.6f));
    v.right = glm::normalize(glm::cross(v.forward, glm::vec3(0, 1, 0)));
    v.up = glm::cross(v.right, v.forward);
    v.yfov = 1.6f;
    return v;
}

// An orthographic view from the plane z = z0 along +z (sign 1) or -z (-1), x and y within
// halfHeight of 0.5: the middle of the specular test scenes (tests/data/specular/).
inline View alongZView(const Scene& scene, double z0, float sign, float halfHeight = 0.25f) {
    View v;
    v.orthographic = true;
    v.halfHeight = halfHeight;
    v.position = glm::vec3(glm::dvec3(0.5, 0.5, z0) - scene.origin);
    v.forward = {0.0f, 0.0f, sign};
    v.up = {0.0f, 1.0f, 0.0f};
    v.right = glm::cross(v.forward, v.up);
    return v;
}

// An orthographic view straight down (-Y) from world point `above`, half as high as `halfHeight`,
// image rows along -Z: the tests' plan view of a floor.
inline View topDownView(const Scene& scene, const glm::dvec3& above, float halfHeight) {
    View v;
    v.orthographic = true;
    v.halfHeight = halfHeight;
    v.position = glm::vec3(above - scene.origin);
    v.forward = {0, -1, 0};
    v.right = {1, 0, 0};
    v.up = {0, 0, -1};
    return v;
}

// A quad of `material`: two triangles (a, b, c) and (a, c, d), counter-clockwise seen from the front.
inline Surface quad(const std::string& name, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d, int material = 0) {
    Surface q;
    q.name = name;
    q.positions = {a, b, c, d};
    q.triangles = {{0, 1, 2}, {0, 2, 3}};
    q.triangleMaterial = {material, material};
    return q;
}

}  // namespace rad::test
