#include "mesh/patch_textures.h"

#include <algorithm>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "scene/texture_sampling.h"

namespace rad {

glm::dvec2 barycentric(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    const glm::dvec3 e1 = b - a, e2 = c - a, d = p - a;
    const double d11 = glm::dot(e1, e1), d12 = glm::dot(e1, e2), d22 = glm::dot(e2, e2);
    const double p1 = glm::dot(d, e1), p2 = glm::dot(d, e2);
    const double det = d11 * d22 - d12 * d12;
    if (!(det > 0.0)) return {0.0, 0.0};
    return {(d22 * p1 - d12 * p2) / det, (d11 * p2 - d12 * p1) / det};
}

glm::vec2 texCoordAt(const Surface& surface, std::size_t triangle, int set, double b1, double b2) {
    const std::vector<glm::vec2>& uv = surface.texCoords[static_cast<std::size_t>(set)];
    if (uv.empty()) return glm::vec2(0.0f);
    const auto& t = surface.triangles[triangle];
    const glm::dvec2 u0(uv[t[0]]), u1(uv[t[1]]), u2(uv[t[2]]);
    return glm::vec2(u0 + b1 * (u1 - u0) + b2 * (u2 - u0));
}

PatchTextureMeans patchTextureMeans(const Scene& scene, const Mesh& mesh) {
    PatchTextureMeans means;
    means.baseColor.assign(mesh.patches.size(), glm::vec3(1.0f));
    means.emission.assign(mesh.patches.size(), glm::vec3(1.0f));
    means.metalRoughness.assign(mesh.patches.size(), glm::vec3(1.0f));
    means.specular.assign(mesh.patches.size(), glm::vec4(1.0f));
    // At most 2^26 texture lookups in all (seconds on one core), shared among the textured
    // patches, 16 to 16,384 each: a texture far finer than its patches is averaged more coarsely.
    std::size_t textured = 0;
    for (const Patch& patch : mesh.patches) {
        const Material& m = scene.materials[static_cast<std::size_t>(patch.material)];
        textured += (m.baseColorTexture.present() ? 1 : 0) + (m.emissiveTexture.present() ? 1 : 0) +
                    (m.metallicRoughnessTexture.present() ? 1 : 0) + (m.specularTexture.present() ? 1 : 0) +
                    (m.specularColorTexture.present() ? 1 : 0);
    }
    const double mostPoints =
        std::clamp(67108864.0 / static_cast<double>(std::max<std::size_t>(textured, 1)), 16.0, 16384.0);
    for (std::size_t p = 0; p < mesh.patches.size(); ++p) {
        const Patch& patch = mesh.patches[p];
        const Material& material = scene.materials[static_cast<std::size_t>(patch.material)];
        const Face& face = mesh.faces[patch.face];
        const Surface& surface = scene.surfaces[face.sceneSurface];
        const glm::dvec3 a(face.p[0]), b(face.p[1]), c(face.p[2]);
        // COLOR_0 multiplies the base colour: its mean over the patch, the mean of its corners' (it
        // is linear over the face); with a base colour texture, the product of the two means.
        if (!surface.colors.empty()) {
            const auto& t = surface.triangles[face.sceneTriangle];
            const glm::dvec3 c0(surface.colors[t[0]]), c1(surface.colors[t[1]]), c2(surface.colors[t[2]]);
            glm::dvec3 sum(0.0);
            for (std::size_t k = 0; k < 3; ++k) {
                const glm::dvec2 w = barycentric(glm::dvec3(patch.p[k]), a, b, c);
                sum += c0 + w.x * (c1 - c0) + w.y * (c2 - c0);
            }
            means.baseColor[p] = glm::vec3(glm::clamp(sum / 3.0, 0.0, 1.0));
        }
        if (!material.baseColorTexture.present() && !material.emissiveTexture.present() &&
            !material.metallicRoughnessTexture.present() && !material.specularTexture.present() &&
            !material.specularColorTexture.present())
            continue;
        auto uvOf = [&](int set) {
            std::array<glm::vec2, 3> uv;
            for (std::size_t k = 0; k < 3; ++k) {
                const glm::dvec2 w = barycentric(glm::dvec3(patch.p[k]), a, b, c);
                uv[k] = texCoordAt(surface, face.sceneTriangle, set, w.x, w.y);
            }
            return uv;
        };
        auto meanRgba = [&](const TextureRef& ref) {
            const std::array<glm::vec2, 3> uv = uvOf(ref.texCoord);
            return meanOverTriangle(scene.images[static_cast<std::size_t>(ref.image)], ref, uv[0], uv[1], uv[2],
                                    mostPoints);
        };
        auto mean = [&](const TextureRef& ref) { return glm::vec3(meanRgba(ref)); };
        if (material.baseColorTexture.present()) means.baseColor[p] *= mean(material.baseColorTexture);
        if (material.emissiveTexture.present()) means.emission[p] = mean(material.emissiveTexture);
        if (material.metallicRoughnessTexture.present())
            means.metalRoughness[p] = mean(material.metallicRoughnessTexture);
        if (material.specularColorTexture.present()) {
            const glm::vec3 colour = mean(material.specularColorTexture);
            means.specular[p] = glm::vec4(colour, means.specular[p].a);
        }
        if (material.specularTexture.present()) means.specular[p].a = meanRgba(material.specularTexture).a;
    }
    return means;
}

}  // namespace rad
