#pragma once
// The scene as the rest of the program sees it: surfaces in world space, their materials
// and the cameras. Built by the glTF loader; read-only afterwards.

#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/mat3x3.hpp>

namespace rad {

// docs/architecture.md, "Conventions": rho = baseColorFactor.rgb; Le = emissiveFactor x emissive
// strength.
struct Material {
    std::string name;
    glm::vec3 reflectance{1.0f};   // rho per channel, in [0, 1]
    glm::vec3 emission{0.0f};      // emitted radiance Le (W / m^2 / sr) per channel
    bool doubleSided = false;      // emits and reflects on both sides

    bool emits() const { return emission.x > 0.0f || emission.y > 0.0f || emission.z > 0.0f; }
};

// One glTF node's mesh instance, in world space. Triangles are counter-clockwise seen from
// their front side. Vertices are shared only within one glTF primitive, as the file had them.
struct Surface {
    std::string name;
    int node = -1;                                   // glTF node index
    std::vector<glm::vec3> positions;                // world space, metres
    std::vector<std::array<std::uint32_t, 3>> triangles;
    std::vector<int> triangleMaterial;               // index into Scene::materials, per triangle
};

struct Camera {
    enum class Projection { Perspective, Orthographic };
    std::string name;
    Projection projection = Projection::Perspective;
    glm::vec3 position{0.0f};
    glm::mat3 orientation{1.0f};   // columns: right, up, backward (the camera looks down -Z)
    float yfov = 0.8f;             // perspective: vertical field of view, radians
    float aspectRatio = 0.0f;      // width / height; 0 when the file leaves it to the viewer
    float xmag = 1.0f, ymag = 1.0f;  // orthographic half extents
    float znear = 0.01f;
};

struct Bounds {
    glm::vec3 lo{std::numeric_limits<float>::max()};
    glm::vec3 hi{-std::numeric_limits<float>::max()};

    void extend(const glm::vec3& p);
    bool empty() const { return lo.x > hi.x; }
    glm::vec3 extent() const { return empty() ? glm::vec3(0.0f) : hi - lo; }
    double diagonal() const;  // in double: extents near the float range overflow in float
};

struct Scene {
    std::string path;                  // the file it came from, for messages
    // Positions are relative to this world point (the centre of the scene's bounding box, in
    // double), so single precision covers the scene's own extent: world = origin + position.
    glm::dvec3 origin{0.0};
    std::vector<Surface> surfaces;
    std::vector<Material> materials;
    std::vector<Camera> cameras;
    std::vector<std::string> warnings; // things the loader skipped or repaired, for the user

    std::size_t triangleCount() const;
    Bounds bounds() const;
    bool anyEmitter() const;  // whether any triangle's material emits light
};

}  // namespace rad
