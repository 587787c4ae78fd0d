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
 * Both read the elements as the host lays them out (host/device/element_records.h): per
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
#include "element_shape.h"
#include "specular_walk.h"

/* Whether a ray from p along *d leaves the scene: straight, or where the scene has mirrors and
 * glass (-DRAD_SPECULAR_TRANSPORT) by way of them (specular_walk.h, the choices drawn from `key`,
 * up to RAD_SPECULAR_BOUNCES); *weight: what they pass on (1 straight), *d: the direction it
 * leaves in, *passed: whether it met any. The sky's and the environment's light through a window
 * or off a mirror so reaches the elements (kept apart, as the shots' light by way of mirrors and
 * glass is, for the camera pass). */
inline bool reaches_outside(const SceneData* scene, float lift, uint key, float3 p, float3* d, float3* weight,
                            bool* passed) {
    SpecularWalk walk = specular_walk_from(scene, p, *d);
#ifdef RAD_SPECULAR_TRANSPORT
    const uint end = walk_specular(scene, &walk, RAD_SPECULAR_BOUNCES, key, lift, false, 0);
#else
    const uint end = walk.hit.face < 0 ? RAD_WALK_OUTSIDE : RAD_WALK_SURFACE;
#endif
    *d = walk.dir;
    *weight = walk.weight;
    *passed = walk.passed > 0u;
    return end == RAD_WALK_OUTSIDE;
}

/* Whether the point of weights w (of the element's second and third corners) lies in a clear
 * texel of its face's alpha mask. */
inline bool point_is_clear(const SceneGeometry* scene, __global const DirectLightElement* element, float2 w) {
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
 * what it passes on reaches other elements; else diffuse_receiver(). */
inline Hit element_receiver(const SceneData* scene, __global const DirectLightElement* element, float2 w, uint side) {
#ifdef RAD_SPECULAR_TRANSPORT
    const int face = (int)element->face;
    const uint kind = material_kind(scene, face);
    /* the back of an opaque one, where it has no patches (side 1), keeps all it receives */
    if (!material_is_diffuse(kind) && !(side == 1u && !material_transmits(kind))) {
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
    RAD_ELEMENT_OF_WORK_ITEM(e);
    const SceneData scene = RAD_SCENE_DATA;
    const float sceneLift = scene.about.lift;
    __global const DirectLightElement* element = &elements[e];
    const ElementShape shape = element_shape(element);
    float3 front = (float3)(0.0f), back = (float3)(0.0f);
    const uint points = n * n;
    uint rays = 0u;
    for (uint k = 0u; k < points; ++k) {
        const float2 w = midpoint_rule_point(k, n);
        if (point_is_clear(&scene.geometry, element, w)) continue;
        /* Both sides through one call, so the traversal is inlined once. */
        for (uint side = 0u; side < (shape.blackBack ? 2u : 1u); ++side) {
            const float3 n = side == 0u ? shape.normal : -shape.normal;
            const float3 arriving = punctual_lights_at(&scene, element_origin(&shape, w, n), n,
                                                       element_receiver(&scene, element, w, side), sceneLift, &rays);
            if (side == 0u) front += arriving;
            else back += arriving;
        }
    }
    out[2u * (size_t)e] = (float4)(front / (float)points, 0.0f);
    out[2u * (size_t)e + 1u] = (float4)(back / (float)points, 0.0f);
}

/* The light from outside (environment.h) over element e's front (out[3e], rgb; in w the mean of
 * the first half of its rays less that of the rest, summed over channels, which bounds the
 * result's variance: solver/direct_light.cpp), over its back where that is black (out[3e + 1],
 * from a sixteenth of the rays), and of the front's what came by way of mirrors and glass
 * (out[3e + 2]; reaches_outside), from `rays` rays.
 *   A uniform sky (or black): every ray cosine-distributed, and the result the fraction that
 *     leaves the scene (what mirrors and glass on the way pass on): the host multiplies it by
 *     pi L. Ray r starts at point r of a scrambled Sobol sequence over the element and leaves in
 *     direction r of the same sequence's other two dimensions, keyed by (key, e, side).
 *   A map: the mean irradiance, W/m^2: even rays cosine-distributed, odd ones drawn from the
 *     map, each one's L cos / q with q the mixture (p_cosine + p_map) / 2 of the two densities
 *     (multiple importance sampling, balance heuristic); each strategy's rays from its own
 *     sequence, keyed by (key, e, side, strategy). */
__kernel void environment_direct(RAD_KERNEL_PARAMS(RAD_ENVIRONMENT_DIRECT_KERNEL)) {
    RAD_ELEMENT_OF_WORK_ITEM(e);
    const SceneData scene = RAD_SCENE_DATA;
    const Environment env = scene_environment(&scene);
    const bool mapped = env.info.width != 0u;
    const float sceneLift = scene.about.lift;
    __global const DirectLightElement* element = &elements[e];
    const ElementShape shape = element_shape(element);
    const uint elementKey = rad_hash2(key, e);
    const uint rays = raysOf[e];
    float3 sum[2] = {(float3)(0.0f), (float3)(0.0f)};
    float3 bySpecular = (float3)(0.0f);
    /* The front's light summed over channels from the first half of its rays and from the rest:
     * how far they differ bounds the variance of their mean (below). */
    float firstPart = 0.0f, restPart = 0.0f;
    const uint firstHalf = mapped ? rays / 4u * 2u : rays / 2u; /* with a map, as many of each strategy */
    /* A black back's light is only summed over the scene (the light the backs absorb), so it
     * takes a sixteenth of the front's rays, at least one (two, one per strategy, with a map). */
    const uint backRays = mapped ? max(2u, rays / 32u * 2u) : max(1u, rays / 16u);
    for (uint side = 0u; side < (shape.blackBack ? 2u : 1u); ++side) {
        const float3 n = side == 0u ? shape.normal : -shape.normal;
        float3 t, bt;
        frame_about(n, &t, &bt);
        const uint sideRays = side == 0u ? rays : backRays;
        for (uint r = 0u; r < sideRays; ++r) {
            const uint strategy = mapped ? r & 1u : 0u;
            const uint stream = mapped ? 2u * side + strategy : side;
            const uint4 x = scrambled_sobol4(mapped ? r >> 1 : r, rad_hash2(elementKey, stream));
            const float2 w = triangle_barycentrics((float2)(unit_float(x.x), unit_float(x.y)));
            if (point_is_clear(&scene.geometry, element, w)) continue;
            const float3 p = element_origin(&shape, w, n);
            float3 d;
            float mapPdf = 0.0f;
            if (strategy == 0u) {
                const float3 around = cosine_hemisphere((float2)(unit_float(x.z), unit_float(x.w)));
                d = around.x * t + around.y * bt + around.z * n;
                if (mapped) mapPdf = environment_pdf(&env, d);
            } else {
                d = environment_sample(&env, x.zw, &mapPdf);
            }
            const float cosine = dot3(d, n);
            if (mapped && !(cosine > 0.0f)) continue;
            const float3 keeps = receiver_keeps(&scene, element_receiver(&scene, element, w, side), d);
            float3 weight;
            bool passed;
            const uint walkKey = rad_hash2(rad_hash2(elementKey, mapped ? stream + 0x51u : side ^ 0x51u), r);
            if (reaches_outside(&scene, sceneLift, walkKey, p, &d, &weight, &passed)) {
                const float3 arrived =
                    mapped ? weight * keeps * environment_radiance(&env, d) *
                                 (cosine / (0.5f * (cosine * (1.0f / RAD_PI) + mapPdf)))
                           : weight * keeps;
                sum[side] += arrived;
                if (side == 0u) {
                    if (r < firstHalf) firstPart += arrived.x + arrived.y + arrived.z;
                    else restPart += arrived.x + arrived.y + arrived.z;
                }
                if (passed && side == 0u) bySpecular += arrived;
            }
        }
    }
    const float split = firstHalf > 0u ? firstPart / (float)firstHalf - restPart / (float)(rays - firstHalf) : 0.0f;
    out[3u * (size_t)e] = (float4)(sum[0] / (float)rays, split);
    out[3u * (size_t)e + 1u] = (float4)(sum[1] / (float)backRays, 0.0f);
    out[3u * (size_t)e + 2u] = (float4)(bySpecular / (float)rays, 0.0f);
}
