#include "device/element_records.h"

#include <algorithm>
#include <cmath>

#include "mesh/patch_textures.h"
#include "mesh/sampling_tables.h"

namespace rad {

std::vector<DirectLightElement> directLightElements(const Mesh& mesh, const ElementMesh& elements) {
    std::vector<DirectLightElement> out;
    out.reserve(elements.elements().size());
    for (const Element& element : elements.elements()) {
        const Patch& patch = mesh.patches[element.patch];
        DirectLightElement record{};
        float largest = 0.0f;
        for (const glm::vec3& v : patch.p)
            largest = std::max({largest, std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
        for (std::size_t k = 0; k < 3; ++k)
            for (int c = 0; c < 3; ++c) record.corners[k][c] = element.p[k][c];
        for (int c = 0; c < 3; ++c) record.normal[c] = patch.normal[c];
        record.normal[3] = originLift(largest);
        // Where the corners lie in their face, for its alpha mask, and which face it is.
        const Face& face = mesh.faces[patch.face];
        for (std::size_t k = 0; k < 3; ++k) {
            const glm::dvec2 w = barycentric(glm::dvec3(element.p[k]), glm::dvec3(face.p[0]), glm::dvec3(face.p[1]),
                                             glm::dvec3(face.p[2]));
            record.faceWeights[k][0] = static_cast<float>(w.x);
            record.faceWeights[k][1] = static_cast<float>(w.y);
        }
        record.face = patch.face;
        record.blackBack = face.backPatch == kNoPatch ? 1 : 0;
        out.push_back(record);
    }
    return out;
}

}  // namespace rad
