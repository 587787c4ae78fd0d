#pragma once
// What every scene loader does last: surfaces built with their vertices in world space, in
// double, become the Scene's surfaces, relative to the centre of their bounding box, in float.

#include <cstddef>
#include <string>
#include <vector>

#include <glm/ext/vector_double3.hpp>
#include <glm/vec3.hpp>

#include "scene/scene.h"

namespace rad {

// A surface while a loader builds it: triangles, materials, texture coordinates and normals as
// Surface holds them, the positions still in double world coordinates (`world`, indexed as the
// triangles index; Surface::positions is left empty until placeSurfaces fills it).
struct WorldSurface {
    Surface surface;
    std::vector<glm::dvec3> world;
};

// Moves the surfaces so the centre of their bounding box is the origin, in double, before any
// coordinate becomes a float: single precision is then spent on the scene's own extent, not on
// how far from the world's origin a site model sits. Sets scene.origin, drops degenerate
// triangles (judged in the float coordinates the program will use) and appends the surfaces
// that keep a triangle to scene.surfaces, with a warning counting the triangles dropped. Throws
// FileError (naming `path`) for a vertex beyond 1e37 m of the centre.
void placeSurfaces(std::vector<WorldSurface>& building, const std::string& path, Scene& scene);

// A point given in world coordinates, relative to scene.origin, in float; throws FileError
// naming `what` where it lies beyond 1e37 m of the scene.
glm::vec3 relativeToOrigin(const glm::dvec3& world, const Scene& scene, const std::string& path,
                           const std::string& what);

}  // namespace rad
