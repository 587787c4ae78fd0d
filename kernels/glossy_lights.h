/* Light sampling at a rough metal (RAD_SPECULAR_GLOSSY, specular.h): the radiance it reflects
 * toward the ray that met it, from each kind of light, by a shadow ray toward a light sample
 * and f(wo, wi) cos_i (glossy_eval). Punctual lights, which no path can hit, each get their own
 * shadow ray (a light cut's bound takes no account of the lobe); an emitting surface's and an
 * environment map's sample is weighed against the lobe's own direction (drawn by
 * glossy_scatter, density glossy_eval's pdf) by the balance heuristic, so a small lamp's or the
 * sun's blurred reflection is sharp and a wide one is not counted twice. The path tracer and
 * the camera pass call these wherever a path meets a rough metal, and weigh what the drawn
 * direction then finds by the same heuristic. */
#ifndef RADIOSITY_GLOSSY_LIGHTS_H
#define RADIOSITY_GLOSSY_LIGHTS_H

#include "environment.h"
#include "light_tree.h"
#include "specular.h"
#include "surface_lights.h"

/* Every punctual light's reflection at p (lifted off the metal on the ray's side). */
inline float3 punctual_glossy(const SceneData* scene, __global const PunctualLight* lights, uint lightCount,
                              const GlossyLobe* lobe, float3 p, float lift, uint* rays) {
    float3 total = (float3)(0.0f);
    for (uint k = 0u; k < lightCount; ++k) {
        float3 toLight;
        float distance;
        /* I att cos_i / r^2 about the shading normal; glossy_eval has the cosine too */
        const float3 e = punctual_irradiance(&lights[k], p, lobe->ns, &toLight, &distance);
        if (!(fmax(fmax(e.x, e.y), e.z) > 0.0f)) continue;
        float pdf;
        const float3 fcos = glossy_eval(lobe, toLight, &pdf);
        if (!(fmax(fmax(fcos.x, fcos.y), fcos.z) > 0.0f)) continue;
        ++*rays;
        const float3 reaching = shadow_transmittance(scene, p, toLight, distance, lift);
        total += fcos * e * reaching / dot3(toLight, lobe->ns);
    }
    return total;
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

/* All of them: what the metal reflects at p of every punctual light, one emitting surface sample
 * and one environment map sample (the keys of the samples' sequences: rng.h's path_sample). */
inline float3 glossy_direct_light(const SceneData* scene, __global const PunctualLight* lights, uint lightCount,
                                  const SurfaceLights* surface, const Environment* env, const GlossyLobe* lobe,
                                  float3 p, float lift, uint seed, uint pixel, uint surfaceKey, uint mapKey,
                                  uint index, uint* rays) {
    float3 e = (float3)(0.0f);
    if (lightCount > 0u) e += punctual_glossy(scene, lights, lightCount, lobe, p, lift, rays);
    if (surface->count > 0u)
        e += surface_light_glossy(scene, surface, lobe, p, path_sample(seed, pixel, surfaceKey, index), rays);
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
