#pragma once
// The scene as the rest of the program sees it: surfaces in world space, their materials
// and the cameras. Built by the glTF loader; read-only afterwards.

#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <glm/ext/vector_double3.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "scene/environment_map.h"

namespace rad {

// An image as the file holds it: 8-bit RGBA texels, rows from the top (glTF's texture
// coordinate (0, 0) is the image's top-left corner). Colour channels are sRGB-encoded, alpha
// linear.
struct TextureImage {
    std::string name;
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgba;  // width * height * 4
};

// A material's use of an image: which texture coordinates, how they wrap, how the texels are
// filtered, and KHR_texture_transform's affine map (applied to the coordinates first).
struct TextureRef {
    enum class Wrap { Repeat, ClampToEdge, MirroredRepeat };
    int image = -1;    // index into Scene::images; -1: no texture
    int texCoord = 0;  // which TEXCOORD_n set
    Wrap wrapS = Wrap::Repeat, wrapT = Wrap::Repeat;
    bool nearest = false;       // magFilter NEAREST; otherwise bilinear
    bool linear = false;        // data, not colour: read without sRGB decoding (metallicRoughnessTexture)
    glm::mat3 transform{1.0f};  // uv' = (transform * (u, v, 1)).xy
    bool present() const { return image >= 0; }
};

// glTF's metallic-roughness model as the file gave it, and the diffuse reflectance the radiosity
// pass uses (docs/architecture.md, "Conventions"; scene/material_model.h says how one follows
// from the other). The defaults here are a plain diffuse surface; the loader applies glTF's own
// defaults (an absent metallicFactor is 1).
struct Material {
    std::string name;
    glm::vec3 reflectance{1.0f};   // rho per channel, in [0, 1]: what radiosity reflects diffusely
    glm::vec3 emission{0.0f};      // emitted radiance Le (W / m^2 / sr) per channel
    bool doubleSided = false;      // emits and reflects on both sides

    glm::vec3 baseColor{1.0f};  // baseColorFactor.rgb
    float metallic = 0.0f;      // metallicFactor
    float roughness = 1.0f;     // roughnessFactor
    float transmission = 0.0f;  // KHR_materials_transmission
    float ior = 1.5f;           // KHR_materials_ior
    // KHR_materials_specular: the strength of a non-metal's specular layer and the tint of its
    // F0. The default here is no layer (a plain diffuse surface, as STL and PLY models, OBJ
    // materials without Ks and the CSV's materials are); glTF's default, which the loader
    // applies, is 1.
    float specular = 0.0f;
    glm::vec3 specularColor{1.0f};
    TextureRef specularTexture;       // linear: its alpha multiplies specular
    TextureRef specularColorTexture;  // sRGB: its rgb multiplies specularColor
    float thickness = 0.0f;     // KHR_materials_volume's thicknessFactor: > 0 a solid that refracts; 0 thin-walled
    // KHR_materials_volume's attenuation: the colour light keeps after attenuationDistance metres
    // inside the solid (Beer-Lambert); distance 0: none (glTF's default, infinite)
    glm::vec3 attenuationColor{1.0f};
    float attenuationDistance = 0.0f;
    enum class AlphaMode { Opaque, Mask };
    AlphaMode alphaMode = AlphaMode::Opaque;  // BLEND is read as MASK at 0.5 (with a warning)
    float alpha = 1.0f;                       // baseColorFactor.a
    float alphaCutoff = 0.5f;                 // MASK: rays pass where alpha is below this
    TextureRef baseColorTexture;              // multiplies baseColor (and so the reflectance); its alpha masks
    bool metallicRoughnessTextured = false;   // has a metallicRoughnessTexture (metallic varies across it)
    TextureRef metallicRoughnessTexture;      // linear: blue multiplies metallic, green roughness
    TextureRef emissiveTexture;   // multiplies the emitted radiance
    // normalTexture (linear): the normal the surface is shaded by, in the tangent frame of the
    // vertices' normals and tangents (Surface::tangents), x and y times normalScale
    TextureRef normalTexture;
    float normalScale = 1.0f;

    bool emits() const { return emission.x > 0.0f || emission.y > 0.0f || emission.z > 0.0f; }
};

// A KHR_lights_punctual light, placed. Intensities are radiometric: the file's photometric
// intensity (candela, or lux for directional lights) times its colour, over 683 lm/W.
struct Light {
    enum class Type { Point, Spot, Directional };
    std::string name;
    Type type = Type::Point;
    glm::dvec3 position{0.0};                    // relative to Scene::origin, as surfaces are (point, spot)
    glm::dvec3 direction{0.0, 0.0, -1.0};        // unit, the way the light travels (spot axis, directional)
    glm::dvec3 intensity{0.0};                   // W / sr per channel (point, spot), W / m^2 (directional)
    double innerConeAngle = 0.0;                 // spot, radians
    double outerConeAngle = 0.7853981633974483;  // spot, radians (pi / 4, the specification's default)
};

// One glTF node's mesh instance, in world space. Triangles are counter-clockwise seen from
// their front side. Vertices are shared only within one glTF primitive, as the file had them.
struct Surface {
    std::string name;
    int node = -1;                                   // glTF node index
    std::vector<glm::vec3> positions;                // world space, metres
    std::vector<std::array<std::uint32_t, 3>> triangles;
    std::vector<int> triangleMaterial;               // index into Scene::materials, per triangle
    // TEXCOORD_0 and TEXCOORD_1 per vertex, indexed as positions are; empty where the file
    // gives none (every coordinate then reads (0, 0), as glTF viewers read it).
    std::array<std::vector<glm::vec2>, 2> texCoords;
    // NORMAL per vertex, unit, in world space, indexed as positions are; empty where the file
    // gives none, and (0, 0, 0) for vertices of primitives without them: shaded flat.
    std::vector<glm::vec3> normals;
    // COLOR_0 per vertex (linear RGB, its alpha dropped), indexed as positions are: it multiplies
    // the base colour, as glTF defines. Empty where no primitive of the surface has one; (1, 1, 1)
    // at vertices of primitives without.
    std::vector<glm::vec3> colors;
    // Tangent frames per vertex for normal maps (scene/tangents.h): xyz the unit tangent in
    // world space, w +-1 the bitangent's sign (bitangent = cross(normal, tangent) w); the file's
    // TANGENT where it has one, else generated for the triangles whose material has a
    // normalTexture. Empty where no triangle needs one; w = 0 at vertices without a frame.
    std::vector<glm::vec4> tangents;
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
    // The sphere around the box (the box's centre, half its diagonal): where light from outside
    // the scene enters (directional lights, the sky, an environment map).
    glm::dvec3 centre() const { return empty() ? glm::dvec3(0.0) : 0.5 * (glm::dvec3(lo) + glm::dvec3(hi)); }
    double radius() const { return 0.5 * diagonal(); }
};

struct Scene {
    std::string path;                  // the file it came from, for messages ("a.stl, b.stl" for several)
    std::vector<std::string> files;    // every file read (a glTF file, or the mesh files), in order
    // Positions are relative to this world point (the centre of the scene's bounding box, in
    // double), so single precision covers the scene's own extent: world = origin + position.
    glm::dvec3 origin{0.0};
    std::vector<Surface> surfaces;
    std::vector<Material> materials;
    std::vector<TextureImage> images;  // what materials' textures read (TextureRef::image)
    std::vector<Camera> cameras;
    std::vector<Light> lights;
    // Radiance from every direction a ray leaves the scene in (W / m^2 / sr per channel). glTF
    // has no sky: the command line gives it (--sky).
    glm::vec3 sky{0.0f};
    // Or an equirectangular map of that radiance (--environment); null when none. One of the
    // two at most. Shared, not copied: maps are large and never change once read.
    std::shared_ptr<const EnvironmentMap> environment;
    std::vector<std::string> warnings; // things the loader skipped or repaired, for the user

    std::size_t triangleCount() const;
    Bounds bounds() const;
    bool anyEmissiveSurface() const;  // whether any triangle's material emits light
    bool anyEmitter() const;          // an emissive surface, a light, a sky or an environment map
};

}  // namespace rad
