#pragma once
// The mesh formats CAD, scanning and thermal tools write, each read into the same plain record:
// surfaces with their coordinates as the file gives them (in its units, parsed to double, so
// every number reads as a correctly rounded reader reads it), triangles, and materials where the
// format has them. scene/mesh_files.cpp turns these into a Scene.

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/ext/vector_double2.hpp>
#include <glm/ext/vector_double3.hpp>

#include "scene/scene.h"

namespace rad {

struct FileSurface {
    std::string name;
    std::vector<glm::dvec3> positions;
    std::vector<glm::dvec3> normals;  // per vertex, as positions; empty where the file gives none
    // Texture coordinates per vertex, as glTF reads them (v from the image's top row; an OBJ's
    // vt, counted from its bottom, turned over); empty where the file gives none.
    std::vector<glm::dvec2> texCoords;
    // Vertex colours per vertex (linear RGB, decoded from the sRGB values scanners and MeshLab
    // write), as glTF's COLOR_0: they multiply the base colour; empty where the file gives none.
    std::vector<glm::dvec3> colors;
    std::vector<std::array<std::uint32_t, 3>> triangles;  // counter-clockwise seen from the front
    std::vector<int> materials;  // per triangle: index into FileMesh::materials, or -1 (the default)
    std::size_t zeroNormals = 0;  // normals the file gives that have no direction, zero or not finite (shaded flat)
};

// Adds the polygon whose corners are the surface's vertices `polygon` (in order) as triangles
// (scene/polygon_split.h: a fan where it is convex, ear clipping where it is not), each of
// material `material`.
void appendPolygon(const std::vector<std::uint32_t>& polygon, int material, FileSurface& surface);

// A colour component a mesh file stores as an sRGB value in [0, 1] (clamped), as linear.
double srgbComponentToLinear(double value);

struct FileMesh {
    std::vector<FileSurface> surfaces;
    std::vector<Material> materials;
    std::vector<TextureImage> images;  // what the materials' textures name (TextureRef::image)
    std::vector<std::string> warnings;
    std::size_t skippedElements = 0;  // points and lines
    std::vector<std::string> extraFiles;  // other files the scene was read from (MTL files, images)
};

// Wavefront OBJ through tinyobjloader (double precision) with its MTL files: a surface for each
// object or group name (o, g; faces before any take the file's name), polygons split into triangles
// (appendPolygon), Kd the base colour and Ke the emitted radiance of each material, times the
// images map_Kd and map_Ke name (PNG or JPEG, beside the OBJ; their -s, -o and -clamp options);
// d and map_d a cut-out; Ns / Pr, Ka (illum 3) / Pm, Ks and Ni glTF's specular layer and metal,
// map_Bump a normal map and map_Ns / map_Pr and map_refl / map_Pm a metallic-roughness texture,
// as Blender's OBJ importer reads what its exporter writes (docs/guide/inputs.md).
FileMesh readObj(const std::string& path);

// STL, binary (84 + 50 bytes a triangle) or ASCII: the whole file one surface, named after it.
// The facet normals are not read: the corners' order says which side is the front.
FileMesh readStl(const std::string& path);

// PLY, ASCII or binary of either byte order: the vertex element's x, y, z (and nx, ny, nz where
// present), the face element's vertex_indices (or vertex_index) lists split into triangles
// (appendPolygon); other elements and properties are skipped. The whole file one surface, named after it.
FileMesh readPly(const std::string& path);

}  // namespace rad
