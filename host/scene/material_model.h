#pragma once
// How glTF's metallic-roughness material becomes what the radiosity pass reflects (README,
// "Materials"). glTF splits the light a surface scatters into a diffuse part, baseColor x
// (1 - metallic) x (1 - transmission); a metal's specular reflection, F0 = baseColor, with weight
// metallic; a dielectric's specular reflection (F0 from the index of refraction, 4% at 1.5); and
// the light a dielectric transmits, with weight (1 - metallic) x transmission.
//
// Surfaces that reflect in directions (specularKind): a smooth metal (roughness at most 0.05,
// metallic 1) is a mirror, with Schlick's Fresnel from F0 = baseColor; a rough metal (metallic 1,
// roughness above 0.05) reflects by glTF's GGX lobe (alpha = roughness^2, kernels/ggx.h) with the
// same Fresnel; a smooth dielectric that transmits all
// it does not reflect (roughness at most 0.05, metallic 0, transmission 1) is glass, with the
// dielectric Fresnel from its IOR, its transmitted light tinted by baseColor (a solid's once, as
// light enters it; a thin wall's at every crossing), refracted where
// the material has a volume (KHR_materials_volume's thicknessFactor > 0) and passing straight
// through a thin wall otherwise, as glTF defines them. The path tracer, the camera pass and the
// progressive solve's shots (kernels/shoot.cl) follow their reflection and refraction
// (kernels/material.h); the shots give them no diffuse reflectance
// (prepared/patch_system.h's reflectanceBesideSpecular).
//
// A material with a metallicRoughnessTexture, which is not read yet, is none of these unless its
// factors are metallic 0 and smooth (glass), which no texture can change.
//
// Everything else is diffuse, and so are mirrors, rough metals and glass to the matrix solvers:
//   - a partly metallic surface's specular reflection is reflected diffusely: its energy is
//     kept, its direction is not;
//   - a dielectric's specular reflection is left out, as radiosity has always done: its
//     diffuse part keeps the base colour whole;
//   - transmitted light is absorbed (glass is opaque), and the loader warns by name.

#include <glm/vec3.hpp>

#include "scene/scene.h"

namespace rad {

// glTF's default material, which every loader gives triangles without one: white, not
// emissive, single-sided.
inline Material defaultMaterial() {
    Material m;
    m.name = "default";
    return m;
}

// The diffuse reflectance the radiosity pass uses, per channel.
inline glm::vec3 radiosityReflectance(const Material& m) {
    const float diffuse = (1.0f - m.metallic) * (1.0f - m.transmission);
    return m.baseColor * (diffuse + m.metallic);
}

// The specular reflectance at normal incidence, per channel (metals: the base colour; dielectrics:
// from the index of refraction), mixed by metallic as glTF mixes them.
inline glm::vec3 specularReflectance(const Material& m) {
    const float r = m.ior > 0.0f ? (m.ior - 1.0f) / (m.ior + 1.0f) : 1.0f;
    return glm::vec3(r * r) * (1.0f - m.metallic) + m.baseColor * m.metallic;
}

enum class SpecularKind { none, mirror, glossy, glass };

inline SpecularKind specularKind(const Material& m) {
    constexpr float kSmooth = 0.05f;  // roughness up to which a surface is an ideal reflector
    // A metallicRoughnessTexture scales the factors down, texel by texel: it says where the surface
    // is metal and how rough (real assets leave the factors at glTF's defaults, metallic 1 and
    // roughness 1, and paint it). It is not read yet, so unless the factors alone settle the
    // kind (metallic 0 and smooth stay so under any texture: glass), the surface stays diffuse
    // rather than becoming a rough metal everywhere.
    if (m.metallicRoughnessTextured && !(m.metallic <= 0.01f && m.roughness <= kSmooth)) return SpecularKind::none;
    if (m.metallic >= 0.99f) return m.roughness > kSmooth ? SpecularKind::glossy : SpecularKind::mirror;
    if (m.roughness > kSmooth) return SpecularKind::none;
    if (m.metallic <= 0.01f && m.transmission >= 0.99f) return SpecularKind::glass;
    return SpecularKind::none;
}

}  // namespace rad
