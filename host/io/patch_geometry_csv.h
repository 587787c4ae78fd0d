#pragma once
// Where each patch is, for mapping patch-level view factors onto another model (a thermal
// solver's nodes, a ParaView mesh): one CSV row a patch, named as the patch tables name it.

#include <ostream>

#include <glm/ext/vector_double3.hpp>

#include "mesh/mesh.h"

namespace rad {

// patch,surface,area,centroid_x..z,normal_x..z,x0,y0,z0,x1,y1,z1,x2,y2,z2: area in m^2, points in
// the file's world coordinates in metres (the mesh's, plus `origin`), the normal unit and
// pointing to the side the patch belongs to, corners counter-clockwise seen from that side.
void writePatchGeometryCsv(std::ostream& out, const Mesh& mesh, const glm::dvec3& origin);

}  // namespace rad
