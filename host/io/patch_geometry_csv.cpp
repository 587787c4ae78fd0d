#include "io/patch_geometry_csv.h"

#include "formfactor/view_factor_table.h"
#include "io/csv_text.h"

namespace rad {

void writePatchGeometryCsv(std::ostream& out, const Mesh& mesh, const glm::dvec3& origin) {
    out << "patch,surface,area,centroid_x,centroid_y,centroid_z,normal_x,normal_y,normal_z,x0,y0,z0,x1,y1,z1,x2,y2,"
           "z2\n";
    for (std::size_t i = 0; i < mesh.patches.size(); ++i) {
        const Patch& patch = mesh.patches[i];
        glm::dvec3 centroid(0.0);
        for (const glm::vec3& p : patch.p) centroid += glm::dvec3(p) / 3.0;
        out << csvField(patchName(mesh, i)) << ',' << csvField(mesh.surfaces[patch.surface].name) << ','
            << csvNumber(patch.area, 9);
        auto point = [&out](const glm::dvec3& p) {
            for (int c = 0; c < 3; ++c) out << ',' << csvNumber(p[c], 10);
        };
        point(origin + centroid);
        for (int c = 0; c < 3; ++c) out << ',' << csvNumber(patch.normal[c], 9);
        for (const glm::vec3& p : patch.p) point(origin + glm::dvec3(p));
        out << '\n';
    }
}

}  // namespace rad
