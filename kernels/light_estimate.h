/* The one direct-light estimator of the path tracer and the camera pass (and so of the lightmap's
 * texels): the radiance a lobe (material.h: a diffuse surface, a rough metal, a diffuse surface
 * under a specular layer, whose two parts are weighed each as a technique of its own) reflects of the
 * light arriving straight from the lights, by light sampling (next-event estimation), and the
 * weights that keep what a path's own directions find from counting a light twice.
 *
 * Punctual lights, which no path can hit, get shadow rays of their own: at a diffuse surface
 * every light's, or past RAD_EXACT_LIGHTS a light cut (light_tree.h); at a rough metal, whose
 * lobe the cut's bounds do not follow, every light's up to RAD_EXACT_LIGHTS, else one drawn by
 * walking their tree. An emitting surface (surface_lights.h) and an environment map
 * (environment.h) get one sample each, weighed against the lobe's own sampling by the balance
 * heuristic (multiple importance sampling): a small lamp's or the sun's light comes from the light
 * sample, a wide one's from the lobe's directions, and neither counts twice; emission a path's
 * own direction finds (emission_seen, environment_seen) is weighed by the same heuristic. */
#ifndef RADIOSITY_LIGHT_ESTIMATE_H
#define RADIOSITY_LIGHT_ESTIMATE_H

#include "environment.h"
#include "light_tree.h"
#include "material.h"
#include "patch_lookup.h"
#include "surface_lights.h"

/* The lights a path samples besides the scene's punctual lights (light_tree.h reads those from
 * the scene): its emitting patches and its environment. */
typedef struct {
    SurfaceLights surface;
    Environment env;
} SceneLights;

/* The scene's lights; `surfaces` false: no emitting patch is sampled (paths find them by
 * hitting them). */
inline SceneLights scene_lights(const SceneData* scene, bool surfaces) {
    SceneLights l;
    l.surface = scene_surface_lights(scene, surfaces);
    l.env = scene_environment(scene);
    return l;
}

/* Whether the lobe passes the light of the lights behind its surface (a thin rough pane: all,
 * or with `punctual` false, the emitting surfaces and the environment), whose shadow rays then
 * leave from lobe->behind. */
inline bool lobe_two_sided(const Lobe* lobe, bool punctual) {
    return lobe->behindLights == RAD_BEHIND_ALL || (!punctual && lobe->behindLights == RAD_BEHIND_SURFACES);
}

/* One punctual light's reflection by a rough metal's or rough glass's lobe at p (and for a thin
 * pane, its transmission of a light behind it). */
inline float3 punctual_lobe_one(const SceneData* scene, __global const PunctualLight* light, const Lobe* lobe,
                                float3 p, float lift, uint* rays) {
    float3 toLight;
    float distance;
    /* I att cos_i / r^2 about the shading normal; lobe_eval has the cosine too */
    float3 e = punctual_irradiance(light, p, lobe->n, &toLight, &distance);
    bool behind = false;
    if (!(fmax(fmax(e.x, e.y), e.z) > 0.0f) && lobe_two_sided(lobe, true)) {
        e = punctual_irradiance(light, lobe->behind, -lobe->n, &toLight, &distance);
        behind = true;
    }
    if (!(fmax(fmax(e.x, e.y), e.z) > 0.0f)) return (float3)(0.0f);
    float pdf;
    const float3 fcos = lobe_eval(lobe, toLight, &pdf);
    if (!(fmax(fmax(fcos.x, fcos.y), fcos.z) > 0.0f)) return (float3)(0.0f);
    ++*rays;
    const float3 reaching = shadow_transmittance(scene, behind ? lobe->behind : p, toLight, distance, lift);
    return fcos * e * reaching / fabs(dot3(toLight, lobe->n));
}

/* The punctual lights' reflection by a rough metal's lobe at p: the directional ones each
 * exactly, and the point and spot lights each exactly up to RAD_EXACT_LIGHTS of them; past that,
 * one of them drawn by walking their tree (light_tree.h) from the root with u, at each node
 * taking a child with a probability that mixes equal parts of its share of the two bounds on
 * what they can send to p (cluster_bound) and of their intensities (never 0 for a child that
 * can light p), divided by the probability of the draw: without bias, and one shadow ray where
 * a light per ray would cost thousands. */
inline float3 punctual_lobe(const SceneData* scene, const Lobe* lobe, float3 p, float lift, float u, uint* rays) {
    float3 total = (float3)(0.0f);
    __global const PunctualLight* lights = scene->punctualLights;
    const uint lightCount = scene->about.punctualCount, directional = scene->about.directional;
    __global const LightNode* tree = scene->lightTree;
    const uint others = lightCount - directional; /* point and spot lights */
    const uint exact = others > RAD_EXACT_LIGHTS ? directional : lightCount;
    for (uint k = 0u; k < exact; ++k) total += punctual_lobe_one(scene, &lights[k], lobe, p, lift, rays);
    if (others <= RAD_EXACT_LIGHTS) return total;
    int node = 0;
    float probability = 1.0f;
    while (tree[node].left >= 0) {
        __global const LightNode* left = &tree[tree[node].left];
        __global const LightNode* right = &tree[tree[node].right];
        float bl = cluster_bound(left, p, lobe->n), br = cluster_bound(right, p, lobe->n);
        if (lobe_two_sided(lobe, true)) { /* lights behind a thin pane light it too */
            bl = fmax(bl, cluster_bound(left, lobe->behind, -lobe->n));
            br = fmax(br, cluster_bound(right, lobe->behind, -lobe->n));
        }
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
    return total + punctual_lobe_one(scene, &lights[k], lobe, p, lift, rays) / probability;
}

/* One emitting surface sample's reflection by the lobe at p, drawn by u (surface_light_draw). */
inline float3 surface_light_sample(const SceneData* scene, const SurfaceLights* s, const Lobe* lobe, float3 p,
                                   uint4 u, uint* rays) {
    float3 dir = (float3)(0.0f), le;
    float distance, lightPdf;
    bool drawn = surface_light_draw(scene, s, p, u, &dir, &distance, &lightPdf, &le);
    if (drawn && lobe_two_sided(lobe, false) && !(dot3(dir, lobe->ng) > 0.0f)) { /* the same point, from behind the pane */
        p = lobe->behind;
        drawn = surface_light_draw(scene, s, p, u, &dir, &distance, &lightPdf, &le);
    }
    if (!drawn) return (float3)(0.0f);
#ifdef RAD_LAYERS
    if (lobe->kind == RAD_LOBE_LAYERED) {
        const float3 w = layered_light_weight(lobe, dir, lightPdf);
        if (!(fmax(fmax(w.x, w.y), w.z) > 0.0f)) return (float3)(0.0f);
        ++*rays;
        if (trace_within(&scene->geometry, p, dir, distance).face >= 0) return (float3)(0.0f);
        return le * w;
    }
#endif
    float pdf;
    const float3 fcos = lobe_eval(lobe, dir, &pdf);
    if (!(fmax(fmax(fcos.x, fcos.y), fcos.z) > 0.0f)) return (float3)(0.0f);
    ++*rays;
    if (trace_within(&scene->geometry, p, dir, distance).face >= 0) return (float3)(0.0f);
    /* Le f cos / lightPdf x lightPdf / (lightPdf + pdf), one division for the three channels */
    return le * fcos * (1.0f / (lightPdf + pdf));
}

/* One environment map sample's reflection by the lobe at p, drawn by u (environment_sample). */
inline float3 environment_light_sample(const SceneData* scene, const Environment* env, const Lobe* lobe, float3 p,
                                       uint2 u, uint* rays) {
    float mapPdf;
    const float3 toward = environment_sample(env, u, &mapPdf);
    if (!(mapPdf > 0.0f)) return (float3)(0.0f);
#ifdef RAD_LAYERS
    if (lobe->kind == RAD_LOBE_LAYERED) {
        const float3 w = layered_light_weight(lobe, toward, mapPdf);
        if (!(fmax(fmax(w.x, w.y), w.z) > 0.0f)) return (float3)(0.0f);
        ++*rays;
        if (trace_closest(&scene->geometry, p, toward).face >= 0) return (float3)(0.0f);
        return environment_radiance(env, toward) * w;
    }
#endif
    float pdf;
    const float3 fcos = lobe_eval(lobe, toward, &pdf);
    if (!(fmax(fmax(fcos.x, fcos.y), fcos.z) > 0.0f)) return (float3)(0.0f);
    ++*rays;
    if (lobe_two_sided(lobe, false) && !(dot3(toward, lobe->ng) > 0.0f)) p = lobe->behind;
    if (trace_closest(&scene->geometry, p, toward).face >= 0) return (float3)(0.0f);
    return environment_radiance(env, toward) * fcos * (1.0f / (mapPdf + pdf));
}

/* The radiance the lobe reflects at p (already off the surface, on the lit side) of the light
 * arriving straight from the lights: the punctual lights, one emitting surface sample and one
 * environment map sample. The samples come from the sequences keyed by (seed, pixel,
 * surfaceKey) and (seed, pixel, mapKey) at `index` (rng.h's path_sample); lift: as shadow rays
 * take it; *rays counts the shadow rays. */
inline float3 direct_light(const SceneData* scene, const SceneLights* lights, const Lobe* lobe, float3 p, float lift,
                           uint seed, uint pixel, uint surfaceKey, uint mapKey, uint index, uint* rays) {
    float3 reflected = (float3)(0.0f);
    const bool diffuse = lobe->kind == RAD_SPECULAR_NONE;
    /* xyz: a surface sample; w: a point or spot light drawn at a rough metal, past RAD_EXACT_LIGHTS */
    const uint punctual = scene->about.punctualCount;
    const bool draws = lights->surface.count > 0u || (!diffuse && punctual - scene->about.directional > RAD_EXACT_LIGHTS);
    const uint4 drawn = draws ? path_sample(seed, pixel, surfaceKey, index) : (uint4)(0u);
    if (punctual > 0u) {
        if (diffuse)
            reflected += lobe->colour * punctual_lights_at(scene, p, lobe->n, diffuse_receiver(), lift, rays) *
                         (1.0f / RAD_PI);
#ifdef RAD_LAYERS
        else if (lobe->kind == RAD_LOBE_LAYERED) {
            /* the diffuse part as a diffuse surface's (about the face, or its normal map's normal,
             * by the light cut), the layer as a rough metal's (about the shading normal): a lobe
             * of the layer alone */
            reflected += lobe->colour * punctual_lights_at(scene, p, lobe->nd, diffuse_receiver(), lift, rays) *
                         (1.0f / RAD_PI);
            Lobe layer = *lobe;
            layer.colour = (float3)(0.0f);
            reflected += punctual_lobe(scene, &layer, p, lift, unit_float(drawn.w), rays);
        }
#endif
        else
            reflected += punctual_lobe(scene, lobe, p, lift, unit_float(drawn.w), rays);
    }
    if (lights->surface.count > 0u) reflected += surface_light_sample(scene, &lights->surface, lobe, p, drawn, rays);
    if (lights->env.info.width != 0u)
        reflected +=
            environment_light_sample(scene, &lights->env, lobe, p, path_sample(seed, pixel, mapKey, index).xy, rays);
    return reflected;
}

/* The share of the emission Le a path's ray finds at `hit` (on the side of first patch `first`,
 * cosine cosLight there) that counts, the ray drawn with density pdf by the last lobe (< 0: not
 * drawn by a lobe, or no light sample could find it: all of it): the balance heuristic's weight
 * against the emitting patches' light samples. */
inline float3 emission_seen(const SceneData* scene, const SurfaceLights* s, Hit hit, uint first, float3 le, float pdf,
                            float cosLight) {
    if (pdf < 0.0f) return le;
    if (!(fmax(fmax(le.x, le.y), le.z) > 0.0f)) return (float3)(0.0f);
    const uint patch = first + grid_cell_index(scene->geometry.faces[hit.face].subdivision, hit.b1, hit.b2);
    return le * surface_light_hit_weight(scene, s, patch, pdf, hit.t, cosLight);
}

/* The radiance from outside a path's ray finds along dir, drawn with density pdf by the last lobe
 * (< 0: all of it): with a map, weighed against its samples by the balance heuristic. */
inline float3 environment_seen(const Environment* env, float3 dir, float pdf) {
    const float3 outside = environment_radiance(env, dir);
    if (pdf < 0.0f || env->info.width == 0u) return outside;
    return outside * (pdf / (pdf + environment_pdf(env, dir)));
}

#endif
