#pragma once
// Patches: every scene triangle (a "face") split uniformly into n * n similar triangles so that
// no patch edge exceeds the patch size. A face whose material is double-sided gets a second
// set of patches for its back. Patches are grouped by surface side: the patches of one side of
// one surface are contiguous, which is how rays are spread over a surface by area.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "scene/scene.h"
#include "shared_types.h"

namespace rad {

inline constexpr std::uint32_t kNoPatch = RAD_NO_PATCH;  // a side without patches: a black back

// One scene triangle, as the ray tracer sees it.
struct Face {
    std::array<glm::vec3, 3> p;     // world space, counter-clockwise seen from the front
    glm::vec3 normal{0.0f};         // unit, front side
    std::uint32_t subdivision = 1;  // n: the face holds n * n patches per side
    std::uint32_t frontPatch = 0;   // first patch of the front side
    std::uint32_t backPatch = kNoPatch;  // first patch of the back side, or kNoPatch (black back)
    int material = 0;
    std::uint32_t sceneSurface = 0;   // the scene triangle it is: Scene::surfaces[sceneSurface]
    std::uint32_t sceneTriangle = 0;  // .triangles[sceneTriangle] (for its texture coordinates)
    // The file's vertex normals (NORMAL) at p[0], p[1], p[2], unit, in the front side's sense as
    // the file gave them; all zero where it gives none: the face is shaded flat.
    std::array<glm::vec3, 3> shadingNormals{};
    bool smooth() const { return shadingNormals[0] != glm::vec3(0.0f); }
    // The shading normal at point q of the face (interpolated, unit), or zero when flat.
    glm::vec3 shadingNormalAt(const glm::vec3& q) const;
};

struct Patch {
    std::array<glm::vec3, 3> p;     // counter-clockwise seen from the side it belongs to
    glm::vec3 normal{0.0f};         // unit, pointing to the side it emits into
    float area = 0.0f;              // m^2
    std::uint32_t face = 0;
    std::uint32_t surface = 0;      // index into Mesh::surfaces
    int material = 0;
};

// One side of one scene surface: what view factors and reports are about.
struct MeshSurface {
    std::string name;               // the scene surface's name; ":back" appended for a back side
    int sceneSurface = 0;
    bool back = false;
    std::uint32_t firstPatch = 0;
    std::uint32_t patchCount = 0;
    double area = 0.0;              // m^2
};

struct Mesh {
    double patchSize = 0.0;
    std::vector<Face> faces;
    std::vector<Patch> patches;
    std::vector<MeshSurface> surfaces;
};

struct MeshOptions {
    double patchSize = 0.0;                 // metres; <= 0 means defaultPatchSize(scene)
    std::uint64_t maxPatches = 10'000'000;  // refuse meshes larger than this
};

// A patch edge of 1/32 of the scene's bounding-box diagonal: about ten thousand patches for a
// room-like scene, enough to resolve its shading; view factors between surfaces do not depend on it.
double defaultPatchSize(const Scene& scene);

// Throws InputError when the patch size is not a positive finite number or the mesh would
// exceed options.maxPatches (the message gives the count and a patch size that fits).
Mesh buildMesh(const Scene& scene, const MeshOptions& options);

}  // namespace rad
