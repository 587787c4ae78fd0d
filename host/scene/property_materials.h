#pragma once
// Materials from a properties file, for `solve` and `pathtrace` (`--properties FILE.csv`): mesh
// files carry no reflectance (STL, PLY) or only a colour (OBJ's MTL), and a glTF scene's
// materials may need changing for a study. The file is the CSV `exchange --properties` reads,
// one row per surface; these commands read its columns
//   surface                                      the surface's name, as the loader gives it
//   reflectance | reflectance_r,_g,_b            diffuse reflectance in [0, 1], grey or per channel
//   emission    | emission_r,_g,_b               emitted radiance, W / m^2 / sr, grey or per channel
// and leave exchange's (emissivity, temperature, heat_flux) alone, so one file can serve both.
// An empty field keeps what the scene says.

#include <string>

namespace rad {

struct Scene;

// Whether `column` is one of the columns above other than `surface` (exchange accepts them).
bool isMaterialColumn(const std::string& column);
inline constexpr const char* kMaterialColumnsListed =
    "solve and pathtrace read reflectance, reflectance_r, reflectance_g, reflectance_b, emission, emission_r, "
    "emission_g, emission_b";

// Gives every listed surface a diffuse material of the file's reflectance and emission, in place
// of what its triangles had (a listed surface is then neither metal nor glass, and its textures
// are no longer read). Throws FileError naming the file, the line and the problem: an unknown
// column or surface, a surface listed twice, a reflectance outside [0, 1], an emission that is
// negative or above 1e30, both a grey and a per-channel column, a partial set of channels.
void applyPropertyMaterials(Scene& scene, const std::string& path);

}  // namespace rad
