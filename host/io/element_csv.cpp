#include "io/element_csv.h"

#include <glm/geometric.hpp>

#include "io/csv_text.h"

namespace rad {

void writeElementCsv(std::ostream& out, const PreparedScene& scene, const ElementMesh& elements,
                     const std::vector<glm::vec3>& radiosity) {
    const Mesh& mesh = scene.mesh();
    out << "element,surface,patch,level,x,y,z,nx,ny,nz,area,rho_r,rho_g,rho_b,B_r,B_g,B_b\n";
    const std::vector<Element>& all = elements.elements();
    for (std::size_t e = 0; e < all.size(); ++e) {
        const Element& element = all[e];
        const Patch& patch = mesh.patches[element.patch];
        // Positions are kept relative to the scene's origin in single precision; add it back in
        // double so the centroids are where the scene file put them.
        const glm::dvec3 centroid =
            scene.scene().origin + (glm::dvec3(element.p[0]) + glm::dvec3(element.p[1]) + glm::dvec3(element.p[2])) / 3.0;
        const glm::vec3 rho = scene.patches().reflectance[element.patch];
        out << e << ',' << csvField(mesh.surfaces[patch.surface].name) << ',' << element.patch << ','
            << element.level;
        for (int k = 0; k < 3; ++k) out << ',' << csvNumber(centroid[k], 9);
        for (int k = 0; k < 3; ++k) out << ',' << csvNumber(patch.normal[k], 7);
        out << ',' << csvNumber(element.area, 7);
        for (int k = 0; k < 3; ++k) out << ',' << csvNumber(rho[k], 7);
        for (int k = 0; k < 3; ++k) out << ',' << csvNumber(radiosity[e][k], 7);
        out << '\n';
    }
}

}  // namespace rad
