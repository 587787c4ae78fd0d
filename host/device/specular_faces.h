#pragma once
// Which faces are mirrors, rough metals or glass (the kinds of scene/surface_kinds.h), as the
// kernels read them (SpecularFace, kernels/material.h): the kind, the colour, the index of
// refraction (glass) or GGX alpha = roughness^2 (rough metals), and the corners' shading normals. Every kernel that
// follows light by reflection and refraction reads this one table: the radiosity pass's shots (kernels/shoot.cl), the
// camera pass and the path tracer.

#include <vector>

#include <glm/vec3.hpp>

#include "mesh/mesh.h"
#include "scene/scene.h"
#include "shared_types.h"

namespace rad {

struct SpecularFaceTable {
    std::vector<SpecularFace> faces;  // per face where any face is specular, else one entry
    bool any = false;                 // whether any face is
    bool glossy = false;              // whether any is a rough metal (RAD_SPECULAR_GLOSSY)
};

// A mirror's or rough metal's F0 is its material's base colour, or where the material has a base
// colour texture, the mean over the face's patches of `patchReflectance` (the texture's mean
// times the factor: prepared/patch_system.h), when given.
SpecularFaceTable buildSpecularFaces(const Scene& scene, const Mesh& mesh,
                                     const std::vector<glm::vec3>* patchReflectance = nullptr);

}  // namespace rad
