#pragma once
// Meshes in the formats CAD, scanning and thermal tools write: Wavefront OBJ (with its MTL),
// STL (ASCII and binary) and PLY (scene/mesh_readers.h), into a Scene as the glTF loader makes
// it: the same coordinates give the same scene, bit for bit, whichever format holds them.
//
// What becomes a surface: each object or group of an OBJ file (o / g; faces before any, the
// file's name), and each STL or PLY file whole (named by its file name without the extension).
// Materials: an OBJ's MTL gives the base colour (Kd), the emitted radiance (Ke, W / m^2 / sr)
// and the specular layer, metal and maps as Blender reads them (scene/mesh_readers.h: readObj);
// faces without a material, and every STL and PLY face, take glTF's default material (white,
// single-sided; a PLY's vertex colours and TextureFile multiply it). Normals where the file gives
// them per vertex (OBJ vn, PLY nx ny nz); an STL's facet normals are not read (its faces are
// flat, and the winding, not the stored normal, says which side is the front, as in glTF).
// Polygons are split into triangles inside them (scene/polygon_split.h).

#include <string>
#include <vector>

#include "scene/scene.h"

namespace rad {

// Whether the path names a format this reader takes (.obj, .stl, .ply, any case).
bool isMeshFile(const std::string& path);

// Reads every file into one scene, in the order given, with coordinates times metresPerUnit
// (in double, before they become floats). Throws FileError naming the file and the problem for
// a missing or unreadable file, a malformed one (the reader says where), non-finite coordinates,
// or a scene with no triangles; points and lines are skipped and degenerate triangles dropped, both counted in
// Scene::warnings.
Scene loadMeshFiles(const std::vector<std::string>& paths, double metresPerUnit = 1.0);

}  // namespace rad
