#pragma once
// The first kind of emitter: the scene's emissive surfaces. Every patch whose material has an
// emissive factor emits radiance Le (emissiveFactor x KHR_materials_emissive_strength) evenly
// and diffusely from its side, an exitance E = pi Le; the patches shoot that light themselves.

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "light/emitter.h"
#include "mesh/mesh.h"
#include "mesh/patch_textures.h"
#include "scene/scene.h"

namespace rad {

class EmissiveSurfaces : public Emitter {
public:
    // The emitting patches of `mesh`; null when none emits.
    // `textures`: the emissive textures' means per patch (mesh/patch_textures.h).
    static std::unique_ptr<EmissiveSurfaces> find(const Scene& scene, const Mesh& mesh,
                                                  const PatchTextureMeans& textures);

    std::string describe() const override;
    glm::dvec3 power() const override { return power_; }
    EmissionSample sample(const glm::dvec4& u) const override;
    glm::dvec3 irradiance(const glm::dvec3& point, const glm::dvec3& normal) const override;
    void addPatchEmission(std::vector<glm::vec3>& radiance) const override;
    void addDirectSources(std::vector<DirectSource>& sources) const override;

private:
    struct EmittingPatch {
        std::uint32_t patch = 0, surface = 0;
        std::array<glm::dvec3, 3> corners;
        glm::dvec3 normal{0.0};
        glm::vec3 radiance{0.0f};  // Le
        float area = 0.0f;         // the patch's, as the solvers read it
    };
    std::vector<EmittingPatch> patches_;
    std::vector<double> cdf_;  // sampling: running share of the power (summed over channels)
    glm::dvec3 power_{0.0};
};

}  // namespace rad
