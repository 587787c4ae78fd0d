#pragma once
// Glass that glTF says is a thin wall, drawn as the solid its mesh closes: Blender's glTF
// exporter writes glass (Transmission Weight 1) without KHR_materials_volume unless told the
// thickness, so glTF, and the program, draw a closed glass object as a thin-walled shell, where
// Cycles refracts through it. `--solid-glass` asks for Cycles' reading.

#include <string>
#include <vector>

#include "scene/scene.h"

namespace rad {

// Makes each glass material without a volume (transmission 1, thickness 0) a solid (thickness 1,
// which only says "a volume": the mesh gives the distances) where every triangle that uses it
// lies on a closed mesh: within each surface, each edge between that material's triangles, their
// corners welded by position, shared by exactly two of them. A glass material on an open mesh
// (a window pane) stays thin, named in a warning. Returns the names of the materials made solid.
std::vector<std::string> solidifyClosedGlass(Scene& scene);

}  // namespace rad
