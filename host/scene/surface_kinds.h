#pragma once
// The kinds of surface the scattering layer (kernels/material.h) scatters in directions, as the
// host chooses them per material and describes them to the kernels (SpecularFace, one per face:
// device/specular_faces.h). A material no kind takes is diffuse. The built-in kinds follow
// glTF's material model as scene/material_model.h reads it: a smooth metal is a mirror, a rough
// one a GGX metal, a clear dielectric glass (a solid with KHR_materials_volume, else a thin
// pane), smooth or, rougher than kSmoothSurface, a GGX microfacet one.
//
// A new kind is an entry here (its id in kernels/material_kinds.h, which materials it takes, the
// colour and parameter its record carries) and its behaviour in kernels/material.h; a kind that
// no glTF material maps to (a test's) is added with addSurfaceKind.

#include <functional>
#include <string>
#include <vector>

#include <glm/vec4.hpp>

#include "scene/scene.h"
#include "shared_types.h"

namespace rad {

struct SurfaceKind {
    std::string name;
    rad_uint id = RAD_SPECULAR_NONE;  // kernels/material_kinds.h
    std::function<bool(const Material&)> takes;
    // The record's colour (rgb) and parameter (w) for a material of this kind.
    std::function<glm::vec4(const Material&)> describe;
    // A metal's F0 comes from its base colour texture where it has one (the texture's mean over
    // each face, as the patches' reflectance holds it).
    bool textureColour = false;
    // The record's GGX alpha (SpecularFace::alpha: a rough dielectric's); none: 0.
    std::function<float(const Material&)> alpha = nullptr;
};

// The kinds, built-in ones first, then those added, in the order they are asked.
const std::vector<SurfaceKind>& surfaceKinds();

// Adds a kind after the others (one whose id kernels/material.h knows).
void addSurfaceKind(SurfaceKind kind);

// The first kind that takes `material`, or null: the material is diffuse.
const SurfaceKind* surfaceKindOf(const Material& material);

}  // namespace rad
