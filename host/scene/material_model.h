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
// same Fresnel, scaled to give back what single scattering loses (ggx_albedo.h: ggxEnergyScale); a dielectric that transmits all it does not reflect (metallic 0, transmission 1)
// is glass, with the dielectric Fresnel from its IOR, its transmitted light tinted by baseColor (a
// solid's once, as light enters it; a thin wall's at every crossing), refracted where the
// material has a volume (KHR_materials_volume's thicknessFactor > 0; its attenuation then absorbs
// along the light's path inside) and passing straight through a thin wall otherwise, as glTF
// defines them; rougher than 0.05 its interface is a GGX
// microfacet one (kernels/material.h: rough_glass_scatter). The path tracer, the camera pass and the
// progressive solve's shots (kernels/shoot.cl) follow their reflection and refraction
// (kernels/material.h); the shots give them no diffuse reflectance
// (prepared/patch_system.h's reflectanceBesideSpecular).
//
// A material with a metallicRoughnessTexture is none of these unless its factors make it glass
// (metallic 0, transmission 1; its roughness is then the factor's, the texture unread, with a
// warning): where the texture says metal, its layer (below) draws it, texel by texel.
//
// Everything else is diffuse with a specular layer over it (SurfaceLayer below), and so are
// mirrors, rough metals and glass to the matrix solvers:
//   - the layer is glTF's: the dielectric's GGX reflection (F0 from the IOR, scaled and tinted by
//     KHR_materials_specular) mixed by metallic with the metal's (F0 = baseColor), one GGX lobe;
//     the diffuse base keeps what the dielectric layer does not reflect (albedo scaling), so a
//     white surface reflects all it receives at any roughness;
//   - the camera pass and the path tracer draw the layer; the radiosity pass reflects its light
//     diffusely (the layer's mean albedo), so it is neither lost nor counted twice;
//   - transmitted light is absorbed (glass is opaque), and the loader warns by name.

#include <algorithm>

#include <glm/common.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "scene/ggx_albedo.h"
#include "scene/scene.h"
#include "scene/surface_kinds.h"

namespace rad {

// glTF's default material, which every loader gives triangles without one: white, not
// emissive, single-sided.
inline Material defaultMaterial() {
    Material m;
    m.name = "default";
    return m;
}

// The diffuse reflectance the radiosity pass uses, per channel, for a surface with no layer
// (SurfaceLayer::present false); radiosityReflectance below covers both.
inline glm::vec3 plainReflectance(const Material& m) {
    const float diffuse = (1.0f - m.metallic) * (1.0f - m.transmission);
    return m.baseColor * (diffuse + m.metallic);
}

// A dielectric's reflectance at normal incidence from its index of refraction, ((ior - 1) /
// (ior + 1))^2 (4 % at glTF's default 1.5); 1 at ior 0 (KHR_materials_ior's "no refraction").
inline float iorReflectance(const Material& m) {
    const float r = m.ior > 0.0f ? (m.ior - 1.0f) / (m.ior + 1.0f) : 1.0f;
    return r * r;
}

// The specular reflectance at normal incidence, per channel (metals: the base colour; dielectrics:
// from the index of refraction), mixed by metallic as glTF mixes them.
inline glm::vec3 specularReflectance(const Material& m) {
    return glm::vec3(iorReflectance(m)) * (1.0f - m.metallic) + m.baseColor * m.metallic;
}

enum class SpecularKind { none, mirror, glossy, glass };

// The roughness up to which a metal or glass is an ideal reflector (a mirror, smooth glass).
constexpr float kSmoothSurface = 0.05f;

// Glass (a non-metal that transmits all it does not reflect) at any roughness: smooth up to
// kSmoothSurface, above it a GGX microfacet dielectric (kernels/material.h). A metal: a mirror
// when smooth, else a rough (GGX) metal. Anything else is diffuse, under glTF's specular layer.
inline SpecularKind specularKind(const Material& m) {
    if (m.metallic <= 0.01f && m.transmission >= 0.99f) return SpecularKind::glass;
    // A metallicRoughnessTexture scales the factors down, texel by texel: it says where the surface
    // is metal and how rough (real assets leave the factors at glTF's defaults, metallic 1 and
    // roughness 1, and paint it). Unless the factors alone settle the kind (glass), the surface
    // is diffuse with a specular layer that reads the texture where a ray lands (SurfaceLayer),
    // rather than a rough metal everywhere.
    if (m.metallicRoughnessTextured) return SpecularKind::none;
    if (m.metallic >= 0.99f) return m.roughness > kSmoothSurface ? SpecularKind::glossy : SpecularKind::mirror;
    return SpecularKind::none;
}

}  // namespace rad

namespace rad {

// The roughness below which a layer is drawn as if it were this rough: the kernels' GGX lobe
// needs a width, and at 0.05 (alpha 0.0025) a highlight is already a mirror's to the eye.
constexpr float kSmoothestLayer = 0.05f;

// glTF's specular layer over a diffuse surface (SpecularKind::none): one GGX lobe of roughness
// `roughness` whose Fresnel factor is F0 + (F90 - F0) (1 - c)^5,
//   F0  = (1 - metallic) s min(F0(ior) specularColor, 1) + metallic baseColor,
//   F90 = (1 - metallic) s + metallic          (s: KHR_materials_specular's factor),
// s and specularColor times the specularTexture's alpha and the specularColorTexture's rgb,
// over a diffuse base of colour `diffuse` = baseColor (1 - metallic) (1 - transmission), which
// reflects, toward a direction of cosine mu, the share 1 - Ed(mu) that the dielectric's part of the
// layer (`dielectricF0`, `dielectricF90`) leaves it (Ed: its albedo, ggx_albedo.h). So
// f = layer + diffuse (1 - Ed(mu_out)) / pi (albedo scaling by the viewer's direction, as Cycles'
// Principled BSDF does): a white non-metal in a uniform surround reflects exactly what it
// receives toward every viewer (the white furnace), the light single-scattering GGX loses going
// to the base; the form is not reciprocal, so light from one direction near grazing comes back
// slightly more than it brought (Ed(mu_in) + 1 - the mean of Ed). The lobe is scaled to reflect
// the light single scattering loses (ggxEnergyScale), as rough metals are.
struct SurfaceLayer {
    bool present = false;
    glm::vec3 diffuse{0.0f};
    glm::vec3 f0{0.0f};
    float f90 = 0.0f;
    glm::vec3 dielectricF0{0.0f};
    float dielectricF90 = 0.0f;
    float roughness = 1.0f;
    glm::vec3 diffuseKept{1.0f};  // 1 - Ed averaged over the hemisphere (cosine-weighted)
    glm::vec3 layerAlbedo{0.0f};  // the lobe's albedo so averaged
};

// The layer of material m: its base colour times `texture` (the base colour texture's mean where
// it has one), its metallic and roughness factors times `metalRoughness`'s blue and green (the
// metallicRoughnessTexture's mean, linear), and its specular factor and colour times `specular`'s
// alpha and rgb (the means of KHR_materials_specular's specularTexture's alpha and of its
// specularColorTexture). A material whose metallicRoughnessTexture could not be read keeps its
// metal's part diffuse (the factors alone do not say where the metal is).
inline SurfaceLayer surfaceLayer(const Material& m, glm::vec3 texture = glm::vec3(1.0f),
                                 glm::vec3 metalRoughness = glm::vec3(1.0f), glm::vec4 specular = glm::vec4(1.0f)) {
    SurfaceLayer l;
    if (surfaceKindOf(m)) return l;  // a mirror, rough metal, glass or a kind added to the registry
    const bool unread = m.metallicRoughnessTextured && !m.metallicRoughnessTexture.present();
    const bool textured = m.metallicRoughnessTexture.present();
    const float metallic = unread ? 0.0f : m.metallic * (textured ? metalRoughness.z : 1.0f);
    const float roughness = m.roughness * (textured ? metalRoughness.y : 1.0f);
    const glm::vec3 base = m.baseColor * texture;
    const float strength = m.specular * specular.a;
    l.dielectricF0 =
        glm::min(glm::vec3(iorReflectance(m)) * (m.specularColor * glm::vec3(specular)), glm::vec3(1.0f)) * strength;
    l.dielectricF90 = strength;
    // by the factors: a patch where the specularTexture is 0 keeps a layer that reflects nothing
    l.present = m.specular > 0.0f || metallic > 0.0f || (textured && m.metallic > 0.0f);
    if (!l.present) return l;
    l.diffuse = unread ? base * ((1.0f - m.metallic) * (1.0f - m.transmission) + m.metallic)
                       : base * ((1.0f - metallic) * (1.0f - m.transmission));
    l.f0 = (1.0f - metallic) * l.dielectricF0 + metallic * base;
    l.f90 = (1.0f - metallic) * l.dielectricF90 + metallic;
    l.roughness = std::max(roughness, kSmoothestLayer);
    // each lobe's mean albedo, with what ggxEnergyScale restores, taken at the mean of E1 (the
    // kernels scale by the viewer's E1: kernels/material.h, ggx_energy)
    const auto average = ggxAlbedoTable().averageAt(l.roughness);
    const auto albedo = [&](glm::vec3 f0, float f90) {
        glm::vec3 out;
        for (int c = 0; c < 3; ++c)
            out[c] = static_cast<float>((f0[c] * average[0] + (f90 - f0[c]) * average[1]) *
                                        ggxEnergyScale(average[0], average[0], f0[c], f90));
        return out;
    };
    l.diffuseKept = glm::vec3(1.0f) - albedo(l.dielectricF0, l.dielectricF90);
    l.layerAlbedo = albedo(l.f0, l.f90);
    return l;
}

// The diffuse reflectance the radiosity pass uses, per channel: with a layer, its base's share
// and the layer's mean albedo (light reflected diffusely that the layer reflects in directions);
// `texture`, `metalRoughness`, `specular`: the textures' means over the patch (surfaceLayer).
inline glm::vec3 radiosityReflectance(const Material& m, glm::vec3 texture = glm::vec3(1.0f),
                                      glm::vec3 metalRoughness = glm::vec3(1.0f),
                                      glm::vec4 specular = glm::vec4(1.0f)) {
    const SurfaceLayer l = surfaceLayer(m, texture, metalRoughness, specular);
    if (!l.present) return m.reflectance * texture;
    return l.diffuse * l.diffuseKept + l.layerAlbedo;
}

}  // namespace rad
