#pragma once
// A test scene solved by the progressive solver, as the camera pass and the lightmap read it:
// the light arriving at each welded vertex, and the part of it that came by way of mirrors and
// glass.

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "device_fixture.h"
#include "mesh/vertices.h"
#include "solver/progressive_solver.h"

namespace rad::test {

// The solution as the camera pass reads it: the light arriving at each vertex.
struct Solved {
    MeshVertices vertices;
    std::vector<glm::vec3> irradiance;         // at each vertex
    std::vector<glm::vec3> elementIrradiance;  // at each element: what the camera pass's gather rays read
    std::vector<glm::vec3> caustic;  // of it, what came by way of mirrors and glass (empty without)
};

// `result`, where given, receives the solver's own result.
inline Solved solveScene(const TestScene& s, std::uint64_t rays, ProgressiveResult* result = nullptr) {
    ProgressiveOptions options;
    options.rays = rays;
    const ProgressiveResult r = ProgressiveSolver(s, s.elements).solve(options);
    std::vector<glm::vec3> perElement(r.incident.size());
    for (std::size_t e = 0; e < perElement.size(); ++e) {
        const float area = s.elements.elements()[e].area;
        perElement[e] = area > 0.0f ? r.incident[e] / area : glm::vec3(0.0f);
    }
    Solved out{weldVertices(s.mesh(), s.elements), {}, perElement, {}};
    out.irradiance = vertexValues(s.elements, out.vertices, perElement);
    if (!r.caustic.empty()) {
        for (std::size_t e = 0; e < perElement.size(); ++e) {
            const float area = s.elements.elements()[e].area;
            perElement[e] = area > 0.0f ? r.caustic[e] / area : glm::vec3(0.0f);
        }
        out.caustic = vertexValues(s.elements, out.vertices, perElement);
    }
    if (result) *result = r;
    return out;
}

}  // namespace rad::test
