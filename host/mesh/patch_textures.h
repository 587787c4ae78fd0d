#pragma once
// The textures' share of each patch's reflectance and emission: per patch, the mean of its
// material's base colour texture, of its emissive texture, of its metallicRoughnessTexture and
// of its specular textures over the patch (linear RGB; 1 where the material has no such texture). The solvers see a patch's mean; the camera pass shows the
// texture itself (README, "Textures").

#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "mesh/mesh.h"
#include "scene/scene.h"

namespace rad {

struct PatchTextureMeans {
    std::vector<glm::vec3> baseColor;  // multiplies the material's reflectance (with COLOR_0's mean where given)
    std::vector<glm::vec3> emission;   // multiplies the material's emitted radiance
    std::vector<glm::vec3> metalRoughness;  // the metallicRoughnessTexture's (linear): blue metallic, green roughness
    // KHR_materials_specular's: rgb the specularColorTexture's, alpha the specularTexture's alpha,
    // each averaged apart (where the two vary together within a patch, as one RGBA texture may,
    // the radiosity pass's F0 is the product of means, not the mean of products)
    std::vector<glm::vec4> specular;
};

PatchTextureMeans patchTextureMeans(const Scene& scene, const Mesh& mesh);

// Barycentric weights (of corners 1 and 2) of point p in the triangle (a, b, c), in double;
// (0, 0) for a degenerate triangle.
glm::dvec2 barycentric(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c);

// A point's texture coordinates from its barycentric weights (of the face's second and third
// corners) in scene triangle `triangle` of `surface`, in set `set`; (0, 0) where the surface
// has none.
glm::vec2 texCoordAt(const Surface& surface, std::size_t triangle, int set, double b1, double b2);

}  // namespace rad
