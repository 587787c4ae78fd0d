#pragma once
// The radiosity system per patch, as every solver reads it: area, reflectance, and the radiance
// the emitters that are surfaces give it (light/emitter.h). Built once with the prepared scene,
// so no solver or writer reads materials itself.

#include <cstddef>
#include <vector>

#include <glm/vec3.hpp>

#include "light/emitter.h"
#include "mesh/mesh.h"
#include "scene/scene.h"
#include "shared_math.h"

namespace rad {

struct PatchSystem {
    std::vector<float> area;             // m^2 (Patch::area)
    std::vector<glm::vec3> reflectance;  // rho per channel, in [0, 1]
    // The colour the camera pass and the path tracer read at a hit (FaceMaterial): the
    // reflectance, but under a specular layer (scene/material_model.h) the base colour (the
    // factor times the texture's mean), which the kernels split between the diffuse part and a
    // metal's F0 by the metallic there.
    std::vector<glm::vec3> shadingColour;
    std::vector<glm::vec3> emission;     // emitted radiance Le, W / m^2 / sr per channel

    std::size_t size() const { return area.size(); }
    // Emitted exitance E = pi Le, W / m^2 per channel.
    glm::vec3 exitance(std::size_t p) const { return glm::vec3(kPi * glm::dvec3(emission[p])); }
    std::vector<glm::vec3> exitance() const;
};

// `textures`: the base colour textures' means per patch (mesh/patch_textures.h).
PatchSystem buildPatchSystem(const Scene& scene, const Mesh& mesh, const PatchTextureMeans& textures,
                             const Emitters& emitters);

// The diffuse reflectance per patch where light is carried through mirrors and glass (the
// progressive solve's shots): the patch system's, but 0 on both sides of every mirror, rough
// metal and glass face, whose light the shots carry on instead of reflecting it diffusely.
std::vector<glm::vec3> reflectanceBesideSpecular(const PatchSystem& patches, const Scene& scene, const Mesh& mesh);

}  // namespace rad
