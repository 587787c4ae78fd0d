#include "mesh/vertices.h"

#include <cmath>
#include <cstring>
#include <unordered_map>

#include <glm/geometric.hpp>

namespace rad {
namespace {

// A corner position on a surface side, by the exact bits of its coordinates.
struct CornerKey {
    std::uint32_t surface;
    std::uint32_t bits[3];
    bool operator==(const CornerKey& o) const {
        return surface == o.surface && bits[0] == o.bits[0] && bits[1] == o.bits[1] && bits[2] == o.bits[2];
    }
};

struct CornerKeyHash {
    std::size_t operator()(const CornerKey& k) const {
        std::uint64_t h = k.surface * 0x9E3779B97F4A7C15ull;
        for (std::uint32_t b : k.bits) h = (h ^ b) * 0x100000001B3ull;
        return static_cast<std::size_t>(h ^ (h >> 29));
    }
};

std::uint32_t bitsOf(float v) {
    if (v == 0.0f) v = 0.0f;  // -0 and +0 are the same place
    std::uint32_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    return bits;
}

}  // namespace

MeshVertices weldVertices(const Mesh& mesh, float creaseDegrees) {
    const float cosCrease = std::cos(creaseDegrees * 3.14159265f / 180.0f);
    MeshVertices out;
    out.patchCorners.resize(mesh.patches.size());
    // Each position may hold several vertices, one per group of patches whose normals agree.
    std::unordered_map<CornerKey, std::vector<std::uint32_t>, CornerKeyHash> atPosition;
    std::vector<glm::vec3> vertexNormal;
    atPosition.reserve(mesh.patches.size() * 2);
    for (std::size_t p = 0; p < mesh.patches.size(); ++p) {
        const Patch& patch = mesh.patches[p];
        for (int k = 0; k < 3; ++k) {
            const glm::vec3& q = patch.p[k];
            std::vector<std::uint32_t>& candidates =
                atPosition[CornerKey{patch.surface, {bitsOf(q.x), bitsOf(q.y), bitsOf(q.z)}}];
            std::uint32_t vertex = 0xFFFFFFFFu;
            for (std::uint32_t v : candidates)
                if (glm::dot(vertexNormal[v], patch.normal) >= cosCrease) {
                    vertex = v;
                    break;
                }
            if (vertex == 0xFFFFFFFFu) {
                vertex = static_cast<std::uint32_t>(out.positions.size());
                out.positions.push_back(q);
                out.surface.push_back(patch.surface);
                vertexNormal.push_back(patch.normal);
                candidates.push_back(vertex);
            }
            out.patchCorners[p][k] = vertex;
        }
    }
    return out;
}

std::vector<glm::vec3> vertexValues(const Mesh& mesh, const MeshVertices& vertices, const std::vector<glm::vec3>& perPatch) {
    std::vector<glm::dvec3> sum(vertices.positions.size(), glm::dvec3(0.0));
    std::vector<double> weight(vertices.positions.size(), 0.0);
    for (std::size_t p = 0; p < mesh.patches.size(); ++p)
        for (std::uint32_t v : vertices.patchCorners[p]) {
            sum[v] += static_cast<double>(mesh.patches[p].area) * glm::dvec3(perPatch[p]);
            weight[v] += mesh.patches[p].area;
        }
    std::vector<glm::vec3> out(sum.size(), glm::vec3(0.0f));
    for (std::size_t v = 0; v < sum.size(); ++v)
        if (weight[v] > 0.0) out[v] = glm::vec3(sum[v] / weight[v]);
    return out;
}

}  // namespace rad
