/* Light sampling at a rough metal (RAD_SPECULAR_GLOSSY, specular.h): the radiance it reflects
 * toward the ray that met it, from each kind of light, by a shadow ray toward a light sample
 * and f(wo, wi) cos_i (glossy_eval). Punctual lights, which no path can hit, get their own
 * shadow rays, or past RAD_EXACT_LIGHTS one drawn from their tree (punctual_glossy); an emitting
 * surface's and an environment map's sample is weighed against the lobe's own direction (drawn
 * by glossy_scatter, density glossy_eval's pdf) by the balance heuristic, so a small lamp's or
 * the sun's blurred reflection is sharp and a wide one is not counted twice. The path tracer and
 * the camera pass call these wherever a path meets a rough metal, and weigh what the drawn
 * direction then finds by the same heuristic. */
#ifndef RADIOSITY_GLOSSY_LIGHTS_H
#define RADIOSITY_GLOSSY_LIGHTS_H

#include "environment.h"
#include "light_tree.h"
#include "specular.h"
#include "surface_lights.h"

/* One punctual light's reflection at p (lifted off the metal on the ray's side). */
inline float3 punctual_glossy_one(const SceneData* scene, __global const PunctualLight* light, const GlossyLobe* lobe,
                                  float3 p, float lift, uint* rays) {
    float3 toLight;
    float distance;
    /* I att cos_i / r^2 about the shading normal; glossy_eval has the cosine too */
    const float3 e = punctual_irradiance(light, p, lobe->ns, &toLight, &distance);
    if (!(fmax(fmax(e.x, e.y), e.z) > 0.0f)) return (float3)(0.0f);
    float pdf;
    const float3 fcos = glossy_eval(lobe, toLight, &pdf);
    if (!(fmax(fmax(fcos.x, fcos.y), fcos.z) > 0.0f)) return (float3)(0.0f);
    ++*rays;
    const float3 reaching = shadow_transmittance(scene, p, toLight, distance, lift);
    return fcos * e * reaching / dot3(toLight, lobe->ns);
}

/* The punctual lights' reflection at p: the `directional` directional lights (first in `lights`)
 * each exactly, and the point and spot lights each exactly up to RAD_EXACT_LIGHTS of them; past
 * that, one of them drawn by walking their tree (light_tree.h) from the root with u, at each node
 * taking a child with a probability that mixes equal parts of its share of the two bounds on
 * what they can send to p (cluster_bound) and of their intensities (never 0 for a child that
 * can light p), divided by the probability of the draw: without bias, and one shadow ray where
 * a light per ray would cost thousands. */
inline float3 punctual_glossy(const SceneData* scene, __global const PunctualLight* lights, uint lightCount,
                              uint directional, __global const LightNode* tree, const GlossyLobe* lobe, float3 p,
                              float lift, float u, uint* rays) {
    float3 total = (float3)(0.0f);
    const uint others = lightCount - directional; /* point and spot lights */
    const uint exact = others > RAD_EXACT_LIGHTS ? directional : lightCount;
    for (uint k = 0u; k < exact; ++k) total += punctual_glossy_one(scene, &lights[k], lobe, p, lift, rays);
    if (others <= RAD_EXACT_LIGHTS) return total;
    int node = 0;
    float probability = 1.0f;
    while (tree[node].left >= 0) {
        __global const LightNode* left = &tree[tree[node].left];
        __global const LightNode* right = &tree[tree[node].right];
        const float bl = cluster_bound(left, p, lobe->ns), br = cluster_bound(right, p, lobe->ns);
        const float power = left->lo[3] + right->lo[3];
        if (!(bl + br > 0.0f) || !(power > 0.0f)) return total; /* nothing below can light p */
        const float geometric = isinf(bl) ? (isinf(br) ? 0.5f : 1.0f) : (isinf(br) ? 0.0f : bl / (bl + br));
        const float share = 0.5f * geometric + 0.5f * (left->lo[3] / power);
        if (u < share) {
            node = tree[node].left;
            probability *= share;
            u = u / share;
        } else {
            node = tree[node].right;
            probability *= 1.0f - share;
            u = (u - share) / (1.0f - share);
        }
        u = fmin(u, 0x1.fffffep-1f);
    }
    if (!(probability > 0.0f)) return total;
    const uint k = directional + (uint)(-1 - tree[node].left);
    return total + punctual_glossy_one(scene, &lights[k], lobe, p, lift, rays) / probability;
}

/* One emitting surface sample's reflection at p, drawn by u (surface_light_draw). */
inline float3 surface_light_glossy(const SceneData* scene, const SurfaceLights* s, const GlossyLobe* lobe, float3 p,
                                   uint4 u, uint* rays) {
    float3 dir, le;
    float distance, lightPdf;
    if (!surface_light_draw(scene, s, p, u, &dir, &distance, &lightPdf, &le)) return (float3)(0.0f);
    float pdf;
    const float3 fcos = glossy_eval(lobe, dir, &pdf);
    if (!(fmax(fmax(fcos.x, fcos.y), fcos.z) > 0.0f)) return (float3)(0.0f);
    ++*rays;
    if (trace_within(scene, p, dir, distance).face >= 0) return (float3)(0.0f);
    return le * fcos / (lightPdf + pdf); /* Le f cos / lightPdf x lightPdf / (lightPdf + pdf) */
}

/* One environment map sample's reflection at p, drawn by u (environment_sample). */
inline float3 environment_glossy(const SceneData* scene, const Environment* env, const GlossyLobe* lobe, float3 p,
                                 uint2 u, uint* rays) {
    float mapPdf;
    const float3 toward = environment_sample(env, u, &mapPdf);
    if (!(mapPdf > 0.0f)) return (float3)(0.0f);
    float pdf;
    const float3 fcos = glossy_eval(lobe, toward, &pdf);
    if (!(fmax(fmax(fcos.x, fcos.y), fcos.z) > 0.0f)) return (float3)(0.0f);
    ++*rays;
    if (trace_closest(scene, p, toward).face >= 0) return (float3)(0.0f);
    return environment_radiance(env, toward) * fcos / (mapPdf + pdf);
}

/* All of them: what the metal reflects at p of the punctual lights, one emitting surface sample
 * and one environment map sample (the keys of the samples' sequences: rng.h's path_sample). */
inline float3 glossy_direct_light(const SceneData* scene, __global const PunctualLight* lights, uint lightCount,
                                  uint directional, __global const LightNode* tree, const SurfaceLights* surface,
                                  const Environment* env, const GlossyLobe* lobe, float3 p, float lift, uint seed,
                                  uint pixel, uint surfaceKey, uint mapKey, uint index, uint* rays) {
    float3 e = (float3)(0.0f);
    /* xyz: a surface sample; w: a point or spot light, when there are too many for a ray each */
    const bool draws = surface->count > 0u || lightCount - directional > RAD_EXACT_LIGHTS;
    const uint4 drawn = draws ? path_sample(seed, pixel, surfaceKey, index) : (uint4)(0u);
    if (lightCount > 0u)
        e += punctual_glossy(scene, lights, lightCount, directional, tree, lobe, p, lift, unit_float(drawn.w), rays);
    if (surface->count > 0u) e += surface_light_glossy(scene, surface, lobe, p, drawn, rays);
    if (env->info.width != 0u)
        e += environment_glossy(scene, env, lobe, p, path_sample(seed, pixel, mapKey, index).xy, rays);
    return e;
}

/* The density glossy_scatter drew `dir` with, which what dir finds is weighed by against the
 * light samples; -1 (no weighing) where it is 0. */
inline float glossy_density(const GlossyLobe* lobe, float3 dir) {
    float pdf;
    glossy_eval(lobe, dir, &pdf);
    return pdf > 0.0f ? pdf : -1.0f;
}

#endif
