#include "mesh/vertices.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>
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

CornerKey keyOf(std::uint32_t surface, const glm::vec3& q) { return {surface, {bitsOf(q.x), bitsOf(q.y), bitsOf(q.z)}}; }

// As elements.cpp computes children's corners: the same bits from either end of the edge.
glm::vec3 midpoint(const glm::vec3& a, const glm::vec3& b) { return glm::vec3(0.5 * (glm::dvec3(a) + glm::dvec3(b))); }

constexpr std::uint32_t kNone = 0xFFFFFFFFu;

// Where the file gives vertex normals (NORMAL), its author says where a surface is smooth: two
// corners at one point weld when their interpolated shading normals agree (within
// kSameShadingNormal), whatever the angle between their faces up to kSmoothestFold, and stay
// apart where the normals are split (a hard edge), however flat the fold. Beyond kSmoothestFold
// (a box exported with averaged normals) the faces' own normals decide: averaging light across
// such a fold would smear one wall's light onto the next. Elsewhere the crease angle decides.
constexpr float kSameShadingNormal = 0.99985f;  // cos 1 degree
constexpr float kSmoothestFold = 0.2588f;       // cos 75 degrees

class Welder {
public:
    Welder(const Mesh& mesh, float creaseDegrees) : mesh_(mesh), cosCrease_(std::cos(creaseDegrees * 3.14159265f / 180.0f)) {}

    // The shading normal of patch `p` at q, in its side's sense (zero where the face is flat).
    glm::vec3 shadingAt(const Patch& p, const glm::vec3& q) const {
        const Face& face = mesh_.faces[p.face];
        const glm::vec3 n = face.shadingNormalAt(q);
        return glm::dot(p.normal, face.normal) < 0.0f ? -n : n;
    }

    // The vertex at q on `surface` whose normals agree with `normal` and `shading` (above); made
    // if `create`.
    std::uint32_t find(std::uint32_t surface, const glm::vec3& q, const glm::vec3& normal, const glm::vec3& shading,
                       bool create) {
        std::vector<std::uint32_t>& candidates = atPosition_[keyOf(surface, q)];
        for (std::uint32_t v : candidates) {
            const float fold = glm::dot(normal_[v], normal);
            const bool bothSmooth = shading != glm::vec3(0.0f) && shading_[v] != glm::vec3(0.0f);
            if (bothSmooth && fold >= kSmoothestFold ? glm::dot(shading_[v], shading) >= kSameShadingNormal
                                                     : fold >= cosCrease_)
                return v;
        }
        if (!create) return kNone;
        const auto v = static_cast<std::uint32_t>(out.positions.size());
        out.positions.push_back(q);
        out.surface.push_back(surface);
        normal_.push_back(normal);
        shading_.push_back(shading);
        candidates.push_back(v);
        return v;
    }

    // T-vertices along the edge (a, b) of an element of patch p: midpoints that are vertices,
    // recursively.
    void walkEdge(const Patch& p, const glm::vec3& pa, const glm::vec3& pb, std::uint32_t va, std::uint32_t vb,
                  std::vector<std::uint32_t>& points, std::vector<std::pair<double, MeshVertices::TVertex>>& found) {
        const glm::vec3 pm = midpoint(pa, pb);
        const std::uint32_t vm = find(p.surface, pm, p.normal, shadingAt(p, pm), false);
        if (vm == kNone || vm == va || vm == vb) return;
        found.emplace_back(glm::length(glm::dvec3(pb) - glm::dvec3(pa)), MeshVertices::TVertex{vm, va, vb});
        walkEdge(p, pa, pm, va, vm, points, found);
        points.push_back(vm);
        walkEdge(p, pm, pb, vm, vb, points, found);
    }

    MeshVertices out;

private:
    const Mesh& mesh_;
    float cosCrease_;
    std::unordered_map<CornerKey, std::vector<std::uint32_t>, CornerKeyHash> atPosition_;
    std::vector<glm::vec3> normal_, shading_;
};

}  // namespace

MeshVertices weldVertices(const Mesh& mesh, const ElementMesh& elements, float creaseDegrees) {
    Welder welder(mesh, creaseDegrees);
    const auto& list = elements.elements();
    welder.out.corners.resize(list.size());
    for (std::size_t e = 0; e < list.size(); ++e) {
        const Patch& patch = mesh.patches[list[e].patch];
        for (int k = 0; k < 3; ++k)
            welder.out.corners[e][k] =
                welder.find(patch.surface, list[e].p[k], patch.normal, welder.shadingAt(patch, list[e].p[k]), true);
    }
    welder.out.edgePoints.resize(list.size());
    std::vector<std::pair<double, MeshVertices::TVertex>> found;
    for (std::size_t e = 0; e < list.size(); ++e) {
        const Patch& patch = mesh.patches[list[e].patch];
        for (int k = 0; k < 3; ++k) {
            const int l = (k + 1) % 3;
            welder.walkEdge(patch, list[e].p[k], list[e].p[l], welder.out.corners[e][k], welder.out.corners[e][l],
                            welder.out.edgePoints[e][k], found);
        }
    }
    // Coarse edges first; a vertex named twice keeps its coarsest edge.
    std::stable_sort(found.begin(), found.end(), [](const auto& x, const auto& y) { return x.first > y.first; });
    std::vector<char> constrained(welder.out.positions.size(), 0);
    for (const auto& [length, t] : found)
        if (!constrained[t.vertex]) {
            constrained[t.vertex] = 1;
            welder.out.tVertices.push_back(t);
        }
    return std::move(welder.out);
}

namespace {
// How far a fitted value may reach beyond the means around it, in units of their spread:
// enough to carry a gradient out to a surface's boundary, not enough to ring at a shadow's edge.
constexpr double kReach = 0.5;

// The value at a vertex: a plane fitted by weighted least squares to the means of the elements
// around it, each placed at its centroid and weighted by its area, read at the vertex. Exact
// for light that varies linearly, whatever the elements' sizes (averaging the means is not
// where a coarse element meets finer ones, nor at a surface's boundary); kept within half the
// means' spread of their range and never negative, so it does not ring at a shadow's edge.
// No value when the centroids do not fix a plane (fewer than three, or in a line).
std::optional<glm::dvec3> fitAtVertex(const glm::vec3& at, const std::vector<std::uint32_t>& around,
                                      const std::vector<Element>& list, const std::vector<glm::vec3>& perElement) {
    if (around.size() < 3) return std::nullopt;
    glm::dvec3 normal(0.0), lo(1e300), hi(-1e300);
    double weight = 0.0;
    for (std::uint32_t e : around) {
        const auto& p = list[e].p;
        normal += glm::cross(glm::dvec3(p[1]) - glm::dvec3(p[0]), glm::dvec3(p[2]) - glm::dvec3(p[0]));
        weight += list[e].area;
        lo = glm::min(lo, glm::dvec3(perElement[e]));
        hi = glm::max(hi, glm::dvec3(perElement[e]));
    }
    if (!(weight > 0.0) || glm::length(normal) == 0.0) return std::nullopt;
    normal = glm::normalize(normal);
    const glm::dvec3 t1 = glm::normalize(std::fabs(normal.x) < 0.9 ? glm::cross(normal, glm::dvec3(1, 0, 0))
                                                                     : glm::cross(normal, glm::dvec3(0, 1, 0)));
    const glm::dvec3 t2 = glm::cross(normal, t1);
    // Normal equations of f(d) = c + g . d, d the centroid's offset in the tangent plane.
    double m[3][3] = {}, scale = 0.0;
    glm::dvec3 r[3] = {glm::dvec3(0.0), glm::dvec3(0.0), glm::dvec3(0.0)};
    for (std::uint32_t e : around) {
        const auto& p = list[e].p;
        const glm::dvec3 offset = (glm::dvec3(p[0]) + glm::dvec3(p[1]) + glm::dvec3(p[2])) / 3.0 - glm::dvec3(at);
        const double x[3] = {1.0, glm::dot(offset, t1), glm::dot(offset, t2)};
        const double w = list[e].area;
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) m[i][j] += w * x[i] * x[j];
            r[i] += w * x[i] * glm::dvec3(perElement[e]);
        }
        scale = std::max(scale, glm::dot(offset, offset));
    }
    // Cramer's rule for c; the determinant against its size for centroids in a line.
    const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                       m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    if (!(std::fabs(det) > 1e-6 * weight * weight * weight * scale * scale)) return std::nullopt;
    const glm::dvec3 c = (r[0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (r[1] * m[2][2] - m[1][2] * r[2]) +
                          m[0][2] * (r[1] * m[2][1] - m[1][1] * r[2])) / det;
    return glm::clamp(c, glm::max(lo - (hi - lo) * kReach, glm::dvec3(0.0)), hi + (hi - lo) * kReach);
}

glm::dvec3 weightedMean(const std::vector<std::uint32_t>& around, const std::vector<Element>& list,
                        const std::vector<glm::vec3>& perElement) {
    glm::dvec3 sum(0.0);
    double weight = 0.0;
    for (std::uint32_t e : around) {
        sum += static_cast<double>(list[e].area) * glm::dvec3(perElement[e]);
        weight += list[e].area;
    }
    return weight > 0.0 ? sum / weight : glm::dvec3(0.0);
}

}  // namespace

std::vector<glm::vec3> vertexValues(const ElementMesh& elements, const MeshVertices& vertices,
                                    const std::vector<glm::vec3>& perElement) {
    const auto& list = elements.elements();
    std::vector<std::vector<std::uint32_t>> around(vertices.positions.size());
    for (std::uint32_t e = 0; e < list.size(); ++e)
        for (std::uint32_t v : vertices.corners[e]) around[v].push_back(e);
    std::vector<glm::vec3> out(vertices.positions.size(), glm::vec3(0.0f));
    std::vector<std::uint32_t> wider;
    for (std::size_t v = 0; v < out.size(); ++v) {
        std::optional<glm::dvec3> value = fitAtVertex(vertices.positions[v], around[v], list, perElement);
        if (!value) {
            // A corner of a surface, or centroids in a line: the elements around those around it.
            wider.clear();
            for (std::uint32_t e : around[v])
                for (std::uint32_t u : vertices.corners[e]) wider.insert(wider.end(), around[u].begin(), around[u].end());
            std::sort(wider.begin(), wider.end());
            wider.erase(std::unique(wider.begin(), wider.end()), wider.end());
            value = fitAtVertex(vertices.positions[v], wider, list, perElement);
        }
        out[v] = glm::vec3(value ? *value : weightedMean(around[v], list, perElement));
    }
    for (const MeshVertices::TVertex& t : vertices.tVertices) out[t.vertex] = 0.5f * (out[t.a] + out[t.b]);
    return out;
}

}  // namespace rad
