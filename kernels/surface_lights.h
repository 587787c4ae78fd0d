/* Direct light from emissive surfaces by light sampling (next-event estimation), for the camera
 * pass's direct and final-gather modes (view_pass.cl) and the path tracer (pathtrace.cl). The
 * host lists the emitting patches (host/light/light_sampling.h) with a table that picks one in
 * proportion to its power; a point is then drawn uniformly on it, and one shadow ray says
 * whether it is seen. Rays drawn by the cosine that hit a listed patch are weighed against this
 * strategy by the balance heuristic (multiple importance sampling), so light sampling is sharp
 * for small, distant emitters and the cosine rays are for large, near ones, and neither counts
 * a light twice. Emitting patches the host does not list (those with an emissive texture, whose
 * light varies within the patch, and alpha-masked ones) are found by the cosine rays alone,
 * weight 1. */
#ifndef RADIOSITY_SURFACE_LIGHTS_H
#define RADIOSITY_SURFACE_LIGHTS_H

#include "bvh_traverse.h"
#include "sampling.h"
#include "vector_math.h"

typedef struct {
    __global const SurfaceLight* lights;
    __global const uint* ends;         /* the lights' shares of 2^32 by power, then their guide (pick_guided) */
    __global const uint* lightOfPatch; /* per patch: 1 + its light's index, or 0: not listed */
    uint count;
} SurfaceLights;

/* The scene's emitting patches, as sampled (`sampled` false: none is, count 0). */
inline SurfaceLights scene_surface_lights(const SceneData* scene, bool sampled) {
    const SurfaceLights s = {scene->surfaceLights, scene->surfaceLightEnds, scene->lightOfPatch,
                             sampled ? scene->about.surfaceLightCount : 0u};
    return s;
}

/* The density per steradian, seen from a point at squared distance distance2 with the light's
 * cosine cosLight there, with which surface_light_irradiance draws a direction toward light k. */
inline float surface_light_pdf(const SceneData* scene, const SurfaceLights* s, uint k, float distance2,
                               float cosLight) {
    const float area = scene->geometry.triangles[s->lights[k].triangle].normal[3];
    return share_of(s->ends, s->count, k) / area * distance2 / cosLight;
}

/* One light sample toward the listed lights from p: the light drawn by u.x in proportion to its
 * power, a point on it by (u.y, u.z). Sets *dir (unit), *distance (to the point, lifted off the
 * emitter as its own rays are, so a shadow ray stops short of it), *pdf (per steradian) and *le;
 * false where there is no light or the point faces away from p. */
inline bool surface_light_draw(const SceneData* scene, const SurfaceLights* s, float3 p, uint4 u, float3* dir,
                               float* distance, float* pdf, float3* le) {
    if (s->count == 0u) return false;
    const uint k = pick_guided(s->ends, s->ends + s->count, s->count, u.x);
    __global const SurfaceLight* light = &s->lights[k];
    __global const SampleTriangle* t = &scene->geometry.triangles[light->triangle];
    const float3 ln = vload3(0, t->normal);
    const float2 w = triangle_barycentrics((float2)(unit_float(u.y), unit_float(u.z)));
    const float3 q = vload3(0, t->v0) + w.x * vload3(0, t->e1) + w.y * vload3(0, t->e2) + t->v0[3] * ln;
    const float3 d = q - p;
    const float distance2 = dot3(d, d);
    if (!(distance2 > 0.0f)) return false;
    *distance = sqrt(distance2);
    *dir = d / *distance;
    const float cosLight = -dot3(ln, *dir);
    if (!(cosLight > 0.0f)) return false;
    *pdf = surface_light_pdf(scene, s, k, distance2, cosLight);
    *le = vload3(0, light->radiance);
    return *pdf > 0.0f;
}

/* One light sample's estimate of the irradiance at p (unit normal n; p already off the surface)
 * from the listed lights: Le cos / pdf if the point drawn is seen, times the balance heuristic's
 * weight against cosine sampling where `mis` is set. u: the pick (x) and the point (y, z). */
inline float3 surface_light_irradiance(const SceneData* scene, const SurfaceLights* s, float3 p, float3 n, uint4 u,
                                       bool mis, uint* rays) {
    float3 dir, le;
    float distance, pdf;
    if (!surface_light_draw(scene, s, p, u, &dir, &distance, &pdf, &le)) return (float3)(0.0f);
    const float cosSurface = dot3(n, dir);
    if (!(cosSurface > 0.0f)) return (float3)(0.0f);
    ++*rays;
    if (trace_within(&scene->geometry, p, dir, distance).face >= 0) return (float3)(0.0f);
    const float weight = mis ? pdf / (pdf + cosSurface * (1.0f / RAD_PI)) : 1.0f;
    return le * (cosSurface * weight / pdf);
}

/* The balance heuristic's weight for the emitted light a cosine-drawn ray (density cosinePdf)
 * finds on `patch` at distance t, where the light's cosine is cosLight: 1 for a patch the
 * host does not list. */
inline float surface_light_hit_weight(const SceneData* scene, const SurfaceLights* s, uint patch, float cosinePdf,
                                     float t, float cosLight) {
    if (s->count == 0u) return 1.0f;
    const uint listed = s->lightOfPatch[patch];
    if (listed == 0u || !(cosLight > 0.0f)) return 1.0f;
    const float pdf = surface_light_pdf(scene, s, listed - 1u, t * t, cosLight);
    return cosinePdf / (cosinePdf + pdf);
}

#endif
