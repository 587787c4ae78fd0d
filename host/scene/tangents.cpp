#include "scene/tangents.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace rad {
namespace {

// A unit vector perpendicular to unit n (any).
glm::dvec3 anyPerpendicular(const glm::dvec3& n) {
    const glm::dvec3 axis = std::abs(n.x) < 0.9 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 1.0, 0.0);
    return glm::normalize(glm::cross(n, axis));
}

double angleAt(const glm::dvec3& a, const glm::dvec3& b) {
    const double la = glm::length(a), lb = glm::length(b);
    if (!(la > 0.0) || !(lb > 0.0)) return 0.0;
    return std::acos(std::clamp(glm::dot(a, b) / (la * lb), -1.0, 1.0));
}

}  // namespace

void generateTangents(const Surface& surface, int texCoord, const std::vector<bool>& wanted,
                      std::vector<glm::vec4>& tangents) {
    const std::size_t vertices = surface.positions.size();
    tangents.resize(vertices, glm::vec4(0.0f));
    const std::vector<glm::vec2>& uv = surface.texCoords.at(static_cast<std::size_t>(texCoord));
    std::vector<glm::dvec3> sumT(vertices, glm::dvec3(0.0));
    std::vector<double> handedness(vertices, 0.0);  // the angle-weighted vote for w
    std::vector<glm::dvec3> normalOf(vertices, glm::dvec3(0.0));
    std::vector<bool> used(vertices, false);
    for (std::size_t t = 0; t < surface.triangles.size(); ++t) {
        if (t >= wanted.size() || !wanted[t]) continue;
        const auto& tri = surface.triangles[t];
        glm::dvec3 p[3];
        glm::dvec2 st[3];
        for (int k = 0; k < 3; ++k) {
            p[k] = glm::dvec3(surface.positions[tri[k]]);
            st[k] = uv.empty() ? glm::dvec2(0.0) : glm::dvec2(uv[tri[k]]);
        }
        const glm::dvec3 e1 = p[1] - p[0], e2 = p[2] - p[0];
        const glm::dvec2 d1 = st[1] - st[0], d2 = st[2] - st[0];
        const glm::dvec3 faceNormal = glm::cross(e1, e2);
        const double area2 = glm::length(faceNormal);
        const double det = d1.x * d2.y - d2.x * d1.y;
        // dP/du and dP/dv of the triangle's mapping (zero where its coordinates are degenerate)
        const bool mapped = std::abs(det) > 1e-20 && area2 > 0.0;
        const glm::dvec3 dpdu = mapped ? (e1 * d2.y - e2 * d1.y) / det : glm::dvec3(0.0);
        const glm::dvec3 dpdv = mapped ? (e2 * d1.x - e1 * d2.x) / det : glm::dvec3(0.0);
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t v = tri[k];
            used[v] = true;
            glm::dvec3 n = surface.normals.empty() ? glm::dvec3(0.0) : glm::dvec3(surface.normals[v]);
            if (glm::dot(n, n) == 0.0 && area2 > 0.0) n = faceNormal / area2;
            normalOf[v] = n;
            if (!mapped) continue;
            const double weight = angleAt(p[(k + 1) % 3] - p[k], p[(k + 2) % 3] - p[k]);
            const glm::dvec3 along = dpdu - n * glm::dot(n, dpdu);
            const double length = glm::length(along);
            if (!(length > 0.0) || !std::isfinite(length)) continue;
            sumT[v] += weight * along / length;
            // glTF's bitangent points up the image, toward decreasing v: -dP/dv
            handedness[v] += weight * (glm::dot(glm::cross(n, dpdu), -dpdv) < 0.0 ? -1.0 : 1.0);
        }
    }
    for (std::size_t v = 0; v < vertices; ++v) {
        if (!used[v] || tangents[v].w != 0.0f) continue;  // a frame it has (the file's) is kept
        const glm::dvec3 n = normalOf[v];
        if (glm::dot(n, n) == 0.0) continue;  // a degenerate triangle's corner with no normal
        glm::dvec3 t = sumT[v] - n * glm::dot(n, sumT[v]);
        const double length = glm::length(t);
        t = length > 1e-12 && std::isfinite(length) ? t / length : anyPerpendicular(n);
        tangents[v] = glm::vec4(glm::vec3(t), handedness[v] < 0.0 ? -1.0f : 1.0f);
    }
}

void frameNormalMaps(Surface& surface, const std::vector<Material>& materials) {
    for (int set = 0; set < 2; ++set) {
        std::vector<bool> wanted(surface.triangles.size(), false);
        bool any = false;
        for (std::size_t t = 0; t < surface.triangles.size(); ++t) {
            const Material& m = materials[static_cast<std::size_t>(surface.triangleMaterial[t])];
            if (!m.normalTexture.present() || m.normalTexture.texCoord != set) continue;
            bool framed = !surface.tangents.empty();
            for (std::uint32_t v : surface.triangles[t]) framed = framed && surface.tangents[v].w != 0.0f;
            wanted[t] = !framed;
            any = any || !framed;
        }
        if (any) generateTangents(surface, set, wanted, surface.tangents);
    }
}

}  // namespace rad
