#include "mesh/mesh.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <glm/geometric.hpp>

#include "mesh/patch_grid.h"
#include "util/error.h"

namespace rad {
namespace {

double longestEdge(const std::array<glm::vec3, 3>& p) {
    const glm::dvec3 a(p[0]), b(p[1]), c(p[2]);
    return std::max({glm::length(b - a), glm::length(c - b), glm::length(a - c)});
}

double triangleArea(const std::array<glm::vec3, 3>& p) {
    const glm::dvec3 a(p[0]);
    return 0.5 * glm::length(glm::cross(glm::dvec3(p[1]) - a, glm::dvec3(p[2]) - a));
}

glm::vec3 unitNormal(const std::array<glm::vec3, 3>& p) {
    const glm::dvec3 a(p[0]);
    return glm::vec3(glm::normalize(glm::cross(glm::dvec3(p[1]) - a, glm::dvec3(p[2]) - a)));
}

std::string formatSize(double metres) {
    std::ostringstream out;
    out.precision(3);
    out << metres;
    return out.str();
}

// Subdivisions per face and the total patch count, before anything is allocated.
std::vector<std::uint32_t> chooseSubdivisions(const Scene& scene, const MeshOptions& options, double patchSize) {
    std::vector<std::uint32_t> subdivision;
    double total = 0.0;
    double longest = 0.0;
    for (const Surface& surface : scene.surfaces)
        for (std::size_t t = 0; t < surface.triangles.size(); ++t) {
            const auto& tri = surface.triangles[t];
            const std::array<glm::vec3, 3> p{surface.positions[tri[0]], surface.positions[tri[1]],
                                             surface.positions[tri[2]]};
            const double edge = longestEdge(p);
            longest = std::max(longest, edge);
            const double n = std::max(1.0, std::ceil(edge / patchSize));
            const bool twoSides = scene.materials[static_cast<std::size_t>(surface.triangleMaterial[t])].doubleSided;
            total += n * n * (twoSides ? 2.0 : 1.0);
            if (total > static_cast<double>(options.maxPatches)) {
                throw InputError("patch size " + formatSize(patchSize) + " m would make more than " +
                                 std::to_string(options.maxPatches) +
                                 " patches (--max-patches); choose a larger --patch-size");
            }
            subdivision.push_back(static_cast<std::uint32_t>(n));
        }
    return subdivision;
}

}  // namespace

glm::vec3 Face::shadingNormalAt(const glm::vec3& q) const {
    if (!smooth()) return glm::vec3(0.0f);
    const glm::dvec3 a(p[0]), e1 = glm::dvec3(p[1]) - a, e2 = glm::dvec3(p[2]) - a, d = glm::dvec3(q) - a;
    const double d11 = glm::dot(e1, e1), d12 = glm::dot(e1, e2), d22 = glm::dot(e2, e2);
    const double det = d11 * d22 - d12 * d12;
    if (!(det > 0.0)) return glm::vec3(0.0f);
    const double b1 = (d22 * glm::dot(d, e1) - d12 * glm::dot(d, e2)) / det;
    const double b2 = (d11 * glm::dot(d, e2) - d12 * glm::dot(d, e1)) / det;
    const glm::dvec3 n = (1.0 - b1 - b2) * glm::dvec3(shadingNormals[0]) + b1 * glm::dvec3(shadingNormals[1]) +
                         b2 * glm::dvec3(shadingNormals[2]);
    const double length = glm::length(n);
    return length > 1e-12 ? glm::vec3(n / length) : glm::vec3(0.0f);
}

double defaultPatchSize(const Scene& scene) {
    const double diagonal = scene.bounds().diagonal();
    return diagonal > 0.0 ? diagonal / 32.0 : 1.0;
}

Mesh buildMesh(const Scene& scene, const MeshOptions& options) {
    const double patchSize = options.patchSize > 0.0 ? options.patchSize : defaultPatchSize(scene);
    if (!std::isfinite(patchSize) || patchSize <= 0.0)
        throw InputError("the patch size must be a positive number of metres");
    const std::vector<std::uint32_t> subdivision = chooseSubdivisions(scene, options, patchSize);

    Mesh mesh;
    mesh.patchSize = patchSize;
    // Faces first, in scene order, so a face's index is stable whatever the sides are.
    for (std::size_t s = 0; s < scene.surfaces.size(); ++s)
        for (std::size_t t = 0; t < scene.surfaces[s].triangles.size(); ++t) {
            const Surface& surface = scene.surfaces[s];
            const auto& tri = surface.triangles[t];
            Face face;
            face.sceneSurface = static_cast<std::uint32_t>(s);
            face.sceneTriangle = static_cast<std::uint32_t>(t);
            face.p = {surface.positions[tri[0]], surface.positions[tri[1]], surface.positions[tri[2]]};
            face.normal = unitNormal(face.p);
            face.subdivision = subdivision[mesh.faces.size()];
            face.material = surface.triangleMaterial[t];
            if (!surface.normals.empty()) {
                const std::array<glm::vec3, 3> n = {surface.normals[tri[0]], surface.normals[tri[1]],
                                                    surface.normals[tri[2]]};
                if (n[0] != glm::vec3(0.0f) && n[1] != glm::vec3(0.0f) && n[2] != glm::vec3(0.0f))
                    face.shadingNormals = n;
            }
            mesh.faces.push_back(face);
        }

    // Then the patches, one surface side at a time: front sides of a surface, then its back.
    std::size_t firstFace = 0;
    for (std::size_t s = 0; s < scene.surfaces.size(); ++s) {
        const std::size_t faceCount = scene.surfaces[s].triangles.size();
        for (const bool back : {false, true}) {
            MeshSurface side;
            side.name = scene.surfaces[s].name + (back ? ":back" : "");
            side.sceneSurface = static_cast<int>(s);
            side.back = back;
            side.firstPatch = static_cast<std::uint32_t>(mesh.patches.size());
            const auto sideIndex = static_cast<std::uint32_t>(mesh.surfaces.size());
            for (std::size_t f = firstFace; f < firstFace + faceCount; ++f) {
                Face& face = mesh.faces[f];
                if (back && !scene.materials[static_cast<std::size_t>(face.material)].doubleSided) continue;
                (back ? face.backPatch : face.frontPatch) = static_cast<std::uint32_t>(mesh.patches.size());
                forEachGridCell(face.subdivision, [&](GridCell cell) {
                    Patch patch;
                    patch.p = gridCellCorners(face.p, face.subdivision, cell);
                    if (back) std::swap(patch.p[1], patch.p[2]);
                    patch.normal = back ? -face.normal : face.normal;
                    const double area = triangleArea(patch.p);
                    patch.area = static_cast<float>(area);
                    patch.face = static_cast<std::uint32_t>(f);
                    patch.surface = sideIndex;
                    patch.material = face.material;
                    side.area += area;
                    mesh.patches.push_back(patch);
                });
            }
            side.patchCount = static_cast<std::uint32_t>(mesh.patches.size()) - side.firstPatch;
            if (side.patchCount > 0) mesh.surfaces.push_back(side);
        }
        firstFace += faceCount;
    }
    return mesh;
}

}  // namespace rad
