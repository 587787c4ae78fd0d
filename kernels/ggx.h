/* Rough metal (RAD_SPECULAR_GLOSSY, material.h): the GGX (Trowbridge-Reitz) microfacet
 * reflection glTF's metallic-roughness model defines, alpha = roughness^2, Schlick's Fresnel from
 * F0 = the base colour, with Smith's height-correlated masking-shadowing (Heitz, "Understanding
 * the Masking-Shadowing Function in Microfacet-Based BRDFs", JCGT 2014), as pbrt-v4 and Mitsuba
 * evaluate it: single scattering (the light that would bounce between microfacets is lost,
 * which material.h's ggx_energy gives back by scaling the lobe, as Cycles does).
 *
 * Directions are in the local frame of the shading normal (z), both pointing away from the
 * surface: wo toward where the light goes (the viewer), wi toward where it comes from. The BRDF
 *   f(wo, wi) = D(h) G2(wo, wi) F(wo . h) / (4 cos_o cos_i),  h = normalize(wo + wi),
 * is sampled by its visible normals (Heitz, "Sampling the GGX Distribution of Visible Normals",
 * JCGT 2018): pdf(wi) = G1(wo) D(h) / (4 cos_o), so a sample's weight f cos_i / pdf is
 * F(wo . h) G2 / G1(wo), never above 1. Only +, -, *, / and sqrt (sampling.h's concentric
 * disk), so every OpenCL implementation rounds alike. */
#ifndef RADIOSITY_GGX_H
#define RADIOSITY_GGX_H

#include "sampling.h"
#include "vector_math.h"

/* Smith's Lambda of the GGX distribution for local direction w (w.z > 0). */
inline float ggx_lambda(float3 w, float alpha) {
    const float tan2 = (w.x * w.x + w.y * w.y) / (w.z * w.z);
    return 0.5f * (sqrt(1.0f + alpha * alpha * tan2) - 1.0f);
}

/* The GGX normal distribution D(m) for unit local microfacet normal m (m.z > 0). Its denominator
 * m.z^2 (a^2 - 1) + 1 written as (m.x^2 + m.y^2) + a^2 m.z^2, which does not cancel near the
 * peak (1.8 % in float at roughness 0.06 the other way). */
inline float ggx_distribution(float3 m, float alpha) {
    const float a2 = alpha * alpha;
    const float d = (m.x * m.x + m.y * m.y) + a2 * (m.z * m.z);
    return a2 / (RAD_PI * d * d);
}

/* A microfacet normal visible from wo (wo.z > 0), drawn from u in [0, 1)^2 with density
 * G1(wo) max(0, wo . m) D(m) / wo.z: the hemisphere configuration (the distribution stretched to
 * alpha 1), a uniform disk point (sampling.h's concentric map) warped onto the half of the disk
 * that wo sees, lifted to the hemisphere and stretched back. */
inline float3 ggx_visible_normal(float3 wo, float alpha, float2 u) {
    const float3 v = normalize3((float3)(alpha * wo.x, alpha * wo.y, wo.z));
    const float len2 = v.x * v.x + v.y * v.y;
    const float3 t1 = len2 > 0.0f ? (float3)(-v.y, v.x, 0.0f) / sqrt(len2) : (float3)(1.0f, 0.0f, 0.0f);
    const float3 t2 = cross3(v, t1);
    const float2 d = concentric_disk(u);
    const float s = 0.5f * (1.0f + v.z);
    const float p2 = (1.0f - s) * sqrt(fmax(0.0f, 1.0f - d.x * d.x)) + s * d.y;
    const float3 h = d.x * t1 + p2 * t2 + sqrt(fmax(0.0f, 1.0f - d.x * d.x - p2 * p2)) * v;
    return normalize3((float3)(alpha * h.x, alpha * h.y, fmax(1e-7f, h.z)));
}

/* G2(wo, wi) / G1(wo), height-correlated: (1 + Lambda(wo)) / (1 + Lambda(wo) + Lambda(wi)). */
inline float ggx_masking_ratio(float3 wo, float3 wi, float alpha) {
    const float lo = ggx_lambda(wo, alpha);
    return (1.0f + lo) / (1.0f + lo + ggx_lambda(wi, alpha));
}

/* f(wo, wi) cos_i without the Fresnel factor, and in *cosine wo . h for it (local directions,
 * both above the surface; 0 otherwise). */
inline float ggx_reflection(float3 wo, float3 wi, float alpha, float* cosine) {
    *cosine = 0.0f;
    if (!(wo.z > 0.0f) || !(wi.z > 0.0f)) return 0.0f;
    const float3 h = normalize3(wo + wi);
    *cosine = fmax(0.0f, dot3(wo, h));
    const float lo = ggx_lambda(wo, alpha), li = ggx_lambda(wi, alpha);
    return ggx_distribution(h, alpha) / ((1.0f + lo + li) * 4.0f * wo.z);
}

/* The density per steradian with which glossy_scatter draws wi (the visible normals' density
 * through the reflection's Jacobian): G1(wo) D(h) / (4 cos_o); 0 below the surface. */
inline float ggx_reflection_pdf(float3 wo, float3 wi, float alpha) {
    if (!(wo.z > 0.0f) || !(wi.z > 0.0f)) return 0.0f;
    const float3 h = normalize3(wo + wi);
    return ggx_distribution(h, alpha) / ((1.0f + ggx_lambda(wo, alpha)) * 4.0f * wo.z);
}

#endif
