#pragma once
// How much light glTF's GGX specular lobe reflects (its directional albedo), as tables over the
// cosine of the direction light leaves in and the roughness, for the layer a dielectric puts
// over its diffuse base (scene/material_model.h: SurfaceLayer) and the kernels that draw it
// (kernels/material.h: layer_albedo).
//
// The lobe is single-scattering GGX (kernels/ggx.h): alpha = roughness^2, Smith's
// height-correlated masking-shadowing, and a Fresnel factor F0 + (F90 - F0) (1 - c)^5 with c the
// cosine between the direction and the microfacet normal (glTF's Schlick form; F90 is 1 for a
// plain dielectric or metal, less where KHR_materials_specular weakens the layer). Being linear in
// F0 and F90, its albedo is F0 E1 + (F90 - F0) E5, where
//   E1(mu, r) = integral of f cos_i without the Fresnel factor,
//   E5(mu, r) = the same with the factor (1 - c)^5,
// mu the cosine of the outgoing direction and r the roughness. Both are computed here once, in
// double precision, by the visible-normal sampling the kernels draw the lobe with, over a
// 64 x 64 grid of strata at each of the table's 32 x 32 points (an independent C++ version of
// the kernels' float code).
#include <array>
#include <cstddef>
#include <vector>

namespace rad {

constexpr std::size_t kAlbedoCosines = 32;    // mu = (i / 31)^2: closer toward grazing, where E turns fastest
constexpr std::size_t kAlbedoRoughness = 32;  // r = j / 31

struct GgxAlbedoTable {
    // (E1, E5) at cosine i and roughness j: values[2 * (j * kAlbedoCosines + i) + {0, 1}]
    std::vector<float> values;
    // The hemispherical averages 2 integral E(mu) mu dmu, per roughness row (the light a lobe
    // reflects of a uniform field, over what arrives): E1 and E5.
    std::array<double, kAlbedoRoughness> average1{}, average5{};

    // Bilinear in (sqrt(mu), r), clamped to the table, as the kernels look it up.
    std::array<double, 2> at(double mu, double roughness) const;
    // The averages, linear in r.
    std::array<double, 2> averageAt(double roughness) const;
};

// Computed on first use (about 0.1 s), then shared.
const GgxAlbedoTable& ggxAlbedoTable();

// The table as the kernels read it (kernels/material.h: layer_albedo, layer_average): the values,
// then each roughness row's averages (E1, E5).
std::vector<float> ggxAlbedoDeviceTable();

// What a GGX lobe of roughness r and Fresnel factor F0 + (F90 - F0) (1 - c)^5 is scaled by so
// that it reflects the light single scattering loses (Cycles' "Multiscatter GGX", after Turquin
// 2019 with the multiple-bounce Fresnel of Kulla and Conty 2017), per channel:
//   1 + Fms (1 - E1) / E1,   Fms = Favg E1avg / (1 - Favg (1 - E1avg)),   Favg = F0 + (F90 - F0) / 21,
// E1 the lobe's albedo at F = 1 toward the viewer (`e1`), E1avg its hemispherical mean. At F = 1
// the lobe then reflects all it receives (E1 x 1 / E1); a coloured one a little less, as light
// that bounces between microfacets meets the Fresnel factor more than once.
// One channel of F0.
double ggxEnergyScale(double e1, double e1Average, double f0, double f90);

// E1 and E5 at one cosine and roughness by the same quadrature as the table, with `strata`
// strata a side (for tests that check the table against a finer sum).
std::array<double, 2> ggxAlbedo(double mu, double roughness, int strata);

}  // namespace rad
