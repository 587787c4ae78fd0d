/* Direct light from emitters the solvers do not shoot (host/light/): punctual lights and the
 * sky, delivered to every element before the first shot. A punctual light's first bounce is
 * where shooting would be noisiest, so it is computed here without noise: at n * n points of
 * each element (the centroids of the n * n similar triangles it splits into, the midpoint rule),
 * each light's closed-form irradiance times what one shadow ray finds reaches the point (all, none,
 * or what thin panes pass: shadow_ray.h); with many lights, a
 * light cut (light_tree.h) instead, deterministic with a bounded error. The sky's is found by
 * cosine-distributed rays from stratified points of the element: the fraction that leaves the
 * scene, times pi L. An environment map's by the same rays, half drawn by the cosine and half from
 * the map (environment.h), each weighted by the mixture of the two densities: the cosine rays
 * find the dim wide sky, the map's the sun.
 *
 * Both read the elements as the host lays them out (host/light/direct_light_kernels.h): per
 * element its three corners on the surface (w of the first: 1 when its back is black, so light
 * that reaches the back is absorbed there and counted), its unit normal (w: how far ray origins
 * are lifted off the surface), and where its corners lie in its face, whose alpha mask may make
 * a point clear: no light arrives there (it passes on to what lies behind). A launch takes the elements first, first + 1, ...; every result
 * depends only on its element, so launches, threads and work-group sizes do not change it. */
#pragma OPENCL FP_CONTRACT OFF

#include "kernel_args.h"
#include "rng.h"
#include "sampling.h"
#include "vector_math.h"
#include "bvh_traverse.h"
#include "light_tree.h"
#include "environment.h"
#include "specular.h"

/* Whether a ray from p along *d leaves the scene: straight, or where the scene has mirrors and
 * glass (-DRAD_SPECULAR_TRANSPORT) by way of them, followed as specular.h scatters (the choice at
 * glass drawn from `key`), up to RAD_SPECULAR_BOUNCES; *weight: what they pass on (1 straight),
 * *d: the direction it leaves in, *passed: whether it met any. The sky's and the environment's
 * light through a window or off a mirror so reaches the elements (kept apart, as the shots' light
 * by way of mirrors and glass is, for the camera pass). */
inline bool reaches_outside(const SceneData* scene, float lift, uint key,
                            float3 p, float3* d, float3* weight, bool* passed) {
    *weight = (float3)(1.0f);
    *passed = false;
    Hit hit = trace_closest(scene, p, *d);
#ifdef RAD_SPECULAR_TRANSPORT
    for (uint bounce = 0u; hit.face >= 0; ++bounce) {
        __global const SpecularFace* surface = &scene->specular[hit.face];
        if (surface->kind == RAD_SPECULAR_NONE || bounce == RAD_SPECULAR_BOUNCES) return false;
        __global const FaceInfo* face = &scene->faces[hit.face];
        const float3 ng = vload3(0, face->normal);
        const bool front = dot3(*d, ng) < 0.0f;
        if (specular_black(surface, (front ? face->frontPatch : face->backPatch) != RAD_NO_PATCH)) return false;
        float3 carried;
        *d = specular_continue(surface, hit, *d, ng, front, specular_choice(key, bounce), lift, &p, &carried);
        *weight *= carried;
        *passed = true;
        hit = trace_closest(scene, p, *d);
    }
#endif
    return hit.face < 0;
}

/* Whether the point of weights w (of the element's second and third corners) lies in a clear
 * texel of its face's alpha mask. */
inline bool point_is_clear(const SceneData* scene, __global const DirectLightElement* element, float2 w) {
#ifndef RAD_ALPHA_MASKS
    return false;
#endif
    if (scene->alpha[0].count == 0u) return false;
    const int face = (int)element->face;
    if (scene->faces[face].alpha == 0u) return false;
    const float2 b0 = vload2(0, element->faceWeights[0]), b1 = vload2(0, element->faceWeights[1]),
                 b2 = vload2(0, element->faceWeights[2]);
    const float2 b = b0 + w.x * (b1 - b0) + w.y * (b2 - b0);
    return masked_out(scene, face, b.x, b.y);
}

/* Where the element's point of weights w lies, when its face is a mirror or glass: the light
 * arriving there counts only as far as the surface keeps it (light_tree.h: receiver_keeps), since
 * what it passes on reaches other elements; else diffuse_receiver(). `side` 1 (a black back)
 * keeps all a mirror's or rough metal's back receives. */
inline Hit element_receiver(const SceneData* scene, __global const DirectLightElement* element, float2 w, uint side) {
#ifdef RAD_SPECULAR_TRANSPORT
    const int face = (int)element->face;
    const uint kind = specular_kind(scene, face);
    if (kind != RAD_SPECULAR_NONE && !(specular_reflects_only(kind) && side == 1u)) {
        const float2 b0 = vload2(0, element->faceWeights[0]), b1 = vload2(0, element->faceWeights[1]),
                     b2 = vload2(0, element->faceWeights[2]);
        const float2 b = b0 + w.x * (b1 - b0) + w.y * (b2 - b0);
        Hit at = diffuse_receiver();
        at.face = face;
        at.b1 = b.x;
        at.b2 = b.y;
        return at;
    }
#endif
    return diffuse_receiver();
}

/* Point k of the n * n midpoint-rule points of a triangle, as barycentric weights of (b, c):
 * the first n (n + 1) / 2 are the centroids of the upright cells, the rest those of the
 * inverted ones. */
inline float2 midpoint_rule_point(uint k, uint n) {
    const uint upright = n * (n + 1u) / 2u;
    const bool inverted = k >= upright;
    uint m = inverted ? k - upright : k;
    const uint rowLength0 = inverted ? n - 1u : n;
    uint row = 0u;
    while (m >= rowLength0 - row) {
        m -= rowLength0 - row;
        ++row;
    }
    const float third = inverted ? 2.0f / 3.0f : 1.0f / 3.0f;
    return (float2)(((float)m + third) / (float)n, ((float)row + third) / (float)n);
}

/* out[2e]: the mean irradiance over element e's front (rgb, W/m^2); out[2e + 1]: over its back
 * where the back is black, else zero. */
__kernel void punctual_direct(RAD_KERNEL_PARAMS(RAD_PUNCTUAL_DIRECT_KERNEL)) {
    const uint e = first + get_global_id(0);
    if (e >= elementCount) return;
    const SceneData scene = RAD_SCENE_DATA;
    __global const PunctualLight* lights = scene.punctualLights;
    __global const LightNode* tree = scene.lightTree;
    const uint lightCount = scene.info->punctualCount, directional = scene.info->directional;
    const float sceneLift = scene.info->lift;
    __global const DirectLightElement* element = &elements[e];
    const float3 a = vload3(0, element->corners[0]), b = vload3(0, element->corners[1]),
                 c = vload3(0, element->corners[2]), normal = vload3(0, element->normal);
    const bool blackBack = element->blackBack != 0u;
    const float lift = element->normal[3];
    float3 front = (float3)(0.0f), back = (float3)(0.0f);
    const uint points = n * n;
    uint rays = 0u;
    for (uint k = 0u; k < points; ++k) {
        const float2 w = midpoint_rule_point(k, n);
        if (point_is_clear(&scene, element, w)) continue;
        const float3 p = a + w.x * (b - a) + w.y * (c - a);
        /* Both sides through one call, so the traversal is inlined once. */
        for (uint side = 0u; side < (blackBack ? 2u : 1u); ++side) {
            const float3 at = side == 0u ? p + lift * normal : p - lift * normal;
            const float3 arriving =
                punctual_lights_at(&scene, lights, lightCount, directional, tree, at, side == 0u ? normal : -normal,
                                   element_receiver(&scene, element, w, side), sceneLift, &rays);
            if (side == 0u) front += arriving;
            else back += arriving;
        }
    }
    out[2u * (size_t)e] = (float4)(front / (float)points, 0.0f);
    out[2u * (size_t)e + 1u] = (float4)(back / (float)points, 0.0f);
}

/* The fraction of `rays` cosine-distributed rays from element e's front that leave the scene
 * (out[3e], rgb: what mirrors and glass on the way pass on, reaches_outside), from its back
 * where that is black (out[3e + 1]), and of the front's, those that left by way of mirrors or
 * glass (out[3e + 2]). Ray r starts at point r of a scrambled Sobol sequence over the element
 * and leaves in direction r of the same sequence's other two dimensions, keyed by (key, e). */
__kernel void sky_direct(RAD_KERNEL_PARAMS(RAD_SKY_DIRECT_KERNEL)) {
    const uint e = first + get_global_id(0);
    if (e >= elementCount) return;
    const SceneData scene = RAD_SCENE_DATA;
    const float sceneLift = scene.info->lift;
    __global const DirectLightElement* element = &elements[e];
    const float3 a = vload3(0, element->corners[0]), b = vload3(0, element->corners[1]),
                 c = vload3(0, element->corners[2]), normal = vload3(0, element->normal);
    const bool blackBack = element->blackBack != 0u;
    const float lift = element->normal[3];
    const uint elementKey = rad_hash2(key, e);
    float3 open[2] = {(float3)(0.0f), (float3)(0.0f)};
    float3 bySpecular = (float3)(0.0f);
    for (uint side = 0u; side < (blackBack ? 2u : 1u); ++side) {
        const float3 n = side == 0u ? normal : -normal;
        float3 t, bt;
        frame_about(n, &t, &bt);
        for (uint r = 0u; r < rays; ++r) {
            const uint4 x = scrambled_sobol4(r, rad_hash2(elementKey, side));
            const float2 w = triangle_barycentrics((float2)(unit_float(x.x), unit_float(x.y)));
            if (point_is_clear(&scene, element, w)) continue;
            const float3 p = a + w.x * (b - a) + w.y * (c - a) + lift * n;
            const float3 around = cosine_hemisphere((float2)(unit_float(x.z), unit_float(x.w)));
            float3 d = around.x * t + around.y * bt + around.z * n, weight;
            const float3 keeps = receiver_keeps(&scene, element_receiver(&scene, element, w, side), d);
            bool passed;
            if (reaches_outside(&scene, sceneLift, rad_hash2(rad_hash2(elementKey, side ^ 0x51u), r), p,
                                &d, &weight, &passed)) {
                open[side] += weight * keeps;
                if (passed && side == 0u) bySpecular += weight * keeps;
            }
        }
    }
    out[3u * (size_t)e] = (float4)(open[0] / (float)rays, 0.0f);
    out[3u * (size_t)e + 1u] = (float4)(open[1] / (float)rays, 0.0f);
    out[3u * (size_t)e + 2u] = (float4)(bySpecular / (float)rays, 0.0f);
}

/* The mean irradiance (rgb, W/m^2) over element e's front from the environment map (out[3e])
 * and over its back where that is black (out[3e + 1]), and of the front's what came by way of
 * mirrors and glass (out[3e + 2]; reaches_outside), from `rays` rays per side: even rays
 * cosine-distributed, odd ones drawn from the map, each one's L cos / q with q the mixture
 * (p_cosine + p_map) / 2 of the two densities (multiple importance sampling, balance
 * heuristic). Each strategy's rays start at the points of its own scrambled Sobol sequence over
 * the element, keyed by (key, e, side, strategy). */
__kernel void environment_direct(RAD_KERNEL_PARAMS(RAD_ENVIRONMENT_DIRECT_KERNEL)) {
    const uint e = first + get_global_id(0);
    if (e >= elementCount) return;
    const SceneData scene = RAD_SCENE_DATA;
    const Environment env = scene_environment(&scene);
    const float sceneLift = scene.info->lift;
    __global const DirectLightElement* element = &elements[e];
    const float3 a = vload3(0, element->corners[0]), b = vload3(0, element->corners[1]),
                 c = vload3(0, element->corners[2]), normal = vload3(0, element->normal);
    const bool blackBack = element->blackBack != 0u;
    const float lift = element->normal[3];
    const uint elementKey = rad_hash2(key, e);
    float3 sum[2] = {(float3)(0.0f), (float3)(0.0f)};
    float3 bySpecular = (float3)(0.0f);
    for (uint side = 0u; side < (blackBack ? 2u : 1u); ++side) {
        const float3 n = side == 0u ? normal : -normal;
        float3 t, bt;
        frame_about(n, &t, &bt);
        for (uint r = 0u; r < rays; ++r) {
            const uint strategy = r & 1u;
            const uint4 x = scrambled_sobol4(r >> 1, rad_hash2(elementKey, 2u * side + strategy));
            const float2 w = triangle_barycentrics((float2)(unit_float(x.x), unit_float(x.y)));
            if (point_is_clear(&scene, element, w)) continue;
            const float3 p = a + w.x * (b - a) + w.y * (c - a) + lift * n;
            float3 d;
            float mapPdf;
            if (strategy == 0u) {
                const float3 around = cosine_hemisphere((float2)(unit_float(x.z), unit_float(x.w)));
                d = around.x * t + around.y * bt + around.z * n;
                mapPdf = environment_pdf(&env, d);
            } else {
                d = environment_sample(&env, x.zw, &mapPdf);
            }
            const float cosine = dot3(d, n);
            if (!(cosine > 0.0f)) continue;
            const float mixture = 0.5f * (cosine * (1.0f / RAD_PI) + mapPdf);
            const float3 keeps = receiver_keeps(&scene, element_receiver(&scene, element, w, side), d);
            float3 weight;
            bool passed;
            if (reaches_outside(&scene, sceneLift,
                                rad_hash2(rad_hash2(elementKey, 2u * side + strategy + 0x51u), r), p, &d, &weight,
                                &passed)) {
                const float3 arrived = weight * keeps * environment_radiance(&env, d) * (cosine / mixture);
                sum[side] += arrived;
                if (passed && side == 0u) bySpecular += arrived;
            }
        }
    }
    out[3u * (size_t)e] = (float4)(sum[0] / (float)rays, 0.0f);
    out[3u * (size_t)e + 1u] = (float4)(sum[1] / (float)rays, 0.0f);
    out[3u * (size_t)e + 2u] = (float4)(bySpecular / (float)rays, 0.0f);
}
