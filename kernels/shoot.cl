/* Ray shooting. Each work item casts one ray of one source (shared_types.h) and finds the
 * column it lands in: the patch (or, for power, the element) hit, or the count of those when it
 * leaves the scene, or one more when it hits the black back of a single-sided face. Rays from a patch are spread uniformly
 * over it and cosine-distributed, so the share of rays landing on j estimates the form factor
 * F_ij. Two kernels: `shoot` counts rays per source row (view factors: the geometry's, every
 * face opaque), `shoot_power` adds each ray's power (progressive refinement), carried on through
 * mirrors and glass where the scene has them (follow_specular). Integer sums make both independent of the order
 * in which work items run. */
#pragma OPENCL FP_CONTRACT OFF

#include "kernel_args.h"
#include "rng.h"
#include "sampling.h"
#include "vector_math.h"
#include "bvh_traverse.h"
#include "patch_lookup.h"
#include "element_lookup.h"
#include "ray_source.h"
#include "fixed_point.h"
#include "specular.h"

/* Keys the random choices of rays that meet glass (a shooter's scramble is keyed otherwise). */
#define RAD_SPECULAR_CHOICES 0x7f4a7c15u

/* The column a hit is counted in. */
inline uint hit_column(const SceneData* scene, Hit hit, float3 dir, uint patchCount) {
    if (hit.face < 0) return patchCount;
    __global const FaceInfo* face = &scene->faces[hit.face];
    const bool front = dot3(dir, vload3(0, face->normal)) < 0.0f;
    const uint first = front ? face->frontPatch : face->backPatch;
    if (first == RAD_NO_PATCH) return patchCount + 1u;
    return first + grid_cell_index(face->subdivision, hit.b1, hit.b2);
}

/* The element at a hit on the side `front` of its face, or where that side has no patches (a
 * single-sided face's back), on the other side. */
inline uint element_on_side(const SceneData* scene, __global const ElementNode* elements, Hit hit, bool front) {
    __global const FaceInfo* face = &scene->faces[hit.face];
    if ((front ? face->frontPatch : face->backPatch) == RAD_NO_PATCH) front = !front;
    const uint first = front ? face->frontPatch : face->backPatch;
    const GridPoint g = grid_locate(face->subdivision, hit.b1, hit.b2);
    float3 w = front ? g.weights : g.weights.xzy; /* a back patch lists its corners 0, 2, 1 */
    return locate_element(elements, first + g.index, &w);
}

/* The element a hit lands on (via its patch's quadtree), or elementCount when the ray left
 * the scene, or elementCount + 1 on a black back. */
inline uint hit_element(const SceneData* scene, __global const ElementNode* elements, Hit hit, float3 dir,
                        uint elementCount) {
    if (hit.face < 0) return elementCount;
    __global const FaceInfo* face = &scene->faces[hit.face];
    const bool front = dot3(dir, vload3(0, face->normal)) < 0.0f;
    if ((front ? face->frontPatch : face->backPatch) == RAD_NO_PATCH) return elementCount + 1u;
    return element_on_side(scene, elements, hit, front);
}

/* Casts ray `ray` of the launch; returns its hit and direction, and its source. */
inline Hit cast(const SceneData* scene, __global const RaySource* sources, uint sourceCount, uint ray,
                RaySource* source, float3* dir) {
    const RaySource src = sources[find_source(sources, sourceCount, ray)];
    const uint4 x = scrambled_sobol4(src.firstSample + (ray - src.firstRay), src.scramble);
    float u0;
    const uint triangle = pick_triangle(scene->cdf, src, x.x, &u0);
    const float4 u = (float4)(u0, unit_float(x.y), unit_float(x.z), unit_float(x.w));
    const SourceRay r = source_ray(&scene->triangles[triangle], u);
    *source = src;
    *dir = r.dir;
    return trace_closest(scene, r.org, r.dir);
}

/* Casts ray `ray` of the launch; returns its column and its source. */
inline uint cast_ray(const SceneData* scene, __global const RaySource* sources, uint sourceCount, uint ray,
                     uint patchCount, RaySource* source) {
    float3 dir;
    const Hit hit = cast(scene, sources, sourceCount, ray, source, &dir);
    return hit_column(scene, hit, dir, patchCount);
}

/* counts[row * (patchCount + 2) + column] += 1 for every ray. */
__kernel void shoot(RAD_KERNEL_PARAMS(RAD_SHOOT_KERNEL)) {
    const uint ray = get_global_id(0);
    if (ray >= rayCount) return;
    const SceneData scene = RAD_SCENE_DATA;
    RaySource src;
    const uint column = cast_ray(&scene, sources, sourceCount, ray, patchCount, &src);
    atomic_inc(&counts[(size_t)src.row * (patchCount + 2u) + column]);
}

/* Casts ray `ray` of a launch of shooters: its origin on the shooter's patch is drawn element by
 * element, in proportion to the unshot power each holds (elementCdf, prepared for the batch by
 * progressive.cl's prepare_shooters), then uniformly within the element. A patch shoots its
 * elements' own distribution of light, not their average: receivers finer than shooters are
 * also finer sources. */
inline Hit cast_from_elements(const SceneData* scene, __global const RaySource* sources, uint sourceCount, uint ray,
                              __global const Shooter* shooters,
                              __global const uint* elementStart, __global const uint* elementCdf,
                              __global const float4* frames, RaySource* source, float3* org, float3* dir) {
    const RaySource src = sources[find_source(sources, sourceCount, ray)];
    const uint4 x = scrambled_sobol4(src.firstSample + (ray - src.firstRay), src.scramble);
    const uint patch = shooters[src.row].patch;
    const uint first = elementStart[patch], count = elementStart[patch + 1u] - first;
    float u0 = unit_float(x.x);
    float2 bary;
    if (count > 1u) {
        /* elementCdf: shares in proportion to the unshot power each element holds */
        const uint e = first + pick_share(elementCdf + first, count, x.x, &u0);
        const float4 frame = frames[e];
        bary = frame.xy + frame.z * triangle_barycentrics((float2)(u0, unit_float(x.y)));
    } else {
        bary = triangle_barycentrics((float2)(u0, unit_float(x.y)));
    }
    const SourceRay r = source_ray_at(&scene->triangles[src.firstTriangle], bary, (float2)(unit_float(x.z), unit_float(x.w)));
    *source = src;
    *org = r.org;
    *dir = r.dir;
    return trace_closest(scene, r.org, r.dir);
}

#ifdef RAD_SPECULAR_TRANSPORT
#define RAD_SHOT_SPECULAR_BOUNCES 32u

/* A shot's ray that lands on a mirror or glass goes on (Sillion and Puech's extended form
 * factors, one ray at a time): reflected, or for glass reflected or refracted by a choice drawn
 * against the Fresnel reflectance, as specular.h scatters it. It carries on the part of its
 * power the surface passes on, per channel; the rest (a mirror's absorption, glass's tint) is
 * delivered to the element it met there, whose diffuse reflectance in the radiosity pass is 0
 * (progressive_solver.cpp), so that part counts as absorbed. The split is in integers
 * (fixed_part), so no power is made or lost, and the sums stay exact and independent of the
 * order of the rays. A mirror's back without patches is black, as any face's; glass passes light
 * on from either side. After RAD_SHOT_SPECULAR_BOUNCES surfaces in a row the ray's power stays
 * with the last one: more than the camera pass follows, since what a shot drops is light lost
 * (a lossless glass sphere of flat faces in the white furnace kept 0.11 % of the light it met
 * at 8, 0.04 % at 32: test_specular_transport.cpp). Leaves in *hit the hit the ray ends on, in
 * `carried` what it brings there and in *passed how many such surfaces it passed; false when it
 * brings nothing. */
inline bool follow_specular(const SceneData* scene, __global const ElementNode* elements, float lift, uint key,
                            float3 org, Hit* hit, float3* dir, ulong* carried, volatile __global uint* power,
                            uint* passed) {
    *passed = 0u;
    for (uint bounce = 0u; hit->face >= 0; ++bounce) {
        __global const SpecularFace* surface = &scene->specular[hit->face];
        if (surface->kind == RAD_SPECULAR_NONE) break;
        __global const FaceInfo* face = &scene->faces[hit->face];
        const float3 ng = vload3(0, face->normal);
        const bool front = dot3(*dir, ng) < 0.0f;
        if (specular_black(surface, (front ? face->frontPatch : face->backPatch) != RAD_NO_PATCH)) break;
        volatile __global uint* sum = power + (size_t)element_on_side(scene, elements, *hit, front) * 6u;
        float3 weight = (float3)(0.0f); /* past the bounce limit: all stays here */
        float3 next = *dir;
        if (bounce < RAD_SHOT_SPECULAR_BOUNCES)
            next = specular_continue(surface, *hit, *dir, ng, front, specular_choice(key, bounce), lift, &org,
                                     &weight);
        const float kept[3] = {weight.x, weight.y, weight.z};
        for (int c = 0; c < 3; ++c) {
            const ulong on = fixed_part(carried[c], kept[c]);
            atomic_add_fixed(sum + 2 * c, carried[c] - on);
            carried[c] = on;
        }
        if (carried[0] == 0ul && carried[1] == 0ul && carried[2] == 0ul) return false;
        *dir = next;
        *hit = trace_closest(scene, org, next);
        ++*passed;
    }
    return true;
}
#endif

/* power[(column * 3 + c) * 2 ..] += ray `ray`'s power in channel c, in 64-bit fixed point, where
 * the column is the element the ray lands on (elementCount: left the scene; + 1: black back);
 * the source's row names its Shooter, whose patch is its only triangle. With specular transport,
 * power that lands on element e after passing mirrors or glass is added once more in column
 * elementCount + 2 + e: the light that arrives there by specular paths (the solution's caustic
 * irradiance, which the camera pass reads apart; kernels/view_pass.cl). */
inline void deliver_ray(const SceneData* scene, __global const RaySource* sources, uint sourceCount, uint ray,
                        __global const Shooter* shooters, volatile __global uint* power,
                        __global const ElementNode* elements, uint elementCount, __global const uint* elementStart,
                        __global const uint* elementCdf, __global const float4* frames, float lift) {
    RaySource src;
    float3 org, dir;
    Hit hit = cast_from_elements(scene, sources, sourceCount, ray, shooters, elementStart, elementCdf, frames, &src,
                                 &org, &dir);
    __global const uint* w = shooters[src.row].weight;
#ifdef RAD_SPECULAR_TRANSPORT
    ulong carried[3];
    for (int c = 0; c < 3; ++c) carried[c] = fixed_value(w[2 * c], w[2 * c + 1]);
    const uint key = rad_hash2(src.scramble ^ RAD_SPECULAR_CHOICES, src.firstSample + (ray - src.firstRay));
    uint passed;
    if (!follow_specular(scene, elements, lift, key, org, &hit, &dir, carried, power, &passed)) return;
    const uint column = hit_element(scene, elements, hit, dir, elementCount);
    volatile __global uint* sum = power + (size_t)column * 6u;
    for (int c = 0; c < 3; ++c) atomic_add_fixed(sum + 2 * c, carried[c]);
    if (passed > 0u && column < elementCount) {
        volatile __global uint* caustic = power + (size_t)(elementCount + 2u + column) * 6u;
        for (int c = 0; c < 3; ++c) atomic_add_fixed(caustic + 2 * c, carried[c]);
    }
#else
    const uint column = hit_element(scene, elements, hit, dir, elementCount);
    volatile __global uint* sum = power + (size_t)column * 6u;
    for (int c = 0; c < 3; ++c)
        if (w[2 * c] != 0u || w[2 * c + 1] != 0u) atomic_add64(sum + 2 * c, w[2 * c], w[2 * c + 1]);
#endif
}

#ifdef RAD_SPECULAR_TRANSPORT
/* What punctual lights send by way of mirrors and glass, which no shadow ray can find (a point
 * light's image in a mirror, the focus of a lens): ray r of rays[3r .. 3r + 2] (origin, unit
 * direction, power per channel in quanta, below 2^32; host/light/punctual_caustics.cpp draws them
 * from the lights by power) goes from its light to what it meets first. Where that is no mirror or glass, the
 * elements' direct light (direct_light.cl) has it, and the ray ends; so it does where it crosses a
 * thin pane straight on (shadow rays cross panes: shadow_ray.h), and goes on as before. At the
 * first surface that reflects or refracts it, the surface keeps its share, which the direct
 * light also counted (light_tree.h: receiver_keeps), and the ray goes on with the rest as the
 * shots' rays do (follow_specular), each surface after keeping its own share, to the element
 * it lands on: power (the shots' columns, one set, in quanta), in its column and once more in
 * its caustic column. */
__kernel void light_caustics(RAD_KERNEL_PARAMS(RAD_LIGHT_CAUSTICS_KERNEL)) {
    const uint r = get_global_id(0);
    if (r >= rayCount) return;
    const SceneData scene = RAD_SCENE_DATA;
    const float lift = scene.info->lift;
    float3 org = rays[3u * (size_t)r].xyz, dir = rays[3u * (size_t)r + 1u].xyz;
    const float3 emitted = rays[3u * (size_t)r + 2u].xyz;
    const uint rayKey = rad_hash2(key, r);
    float3 weight = (float3)(1.0f);
    Hit hit = trace_closest(&scene, org, dir);
    for (uint bounce = 0u;; ++bounce) {
        if (hit.face < 0 || bounce == RAD_SHOT_SPECULAR_BOUNCES) return;
        __global const SpecularFace* surface = &scene.specular[hit.face];
        if (surface->kind == RAD_SPECULAR_NONE) return;
        __global const FaceInfo* face = &scene.faces[hit.face];
        const float3 ng = vload3(0, face->normal);
        const bool front = dot3(dir, ng) < 0.0f;
        if (specular_black(surface, (front ? face->frontPatch : face->backPatch) != RAD_NO_PATCH)) return;
        float3 carried;
        bool through;
        const float3 next = specular_scatter(surface, hit, dir, ng, specular_choice(rayKey, bounce), &carried,
                                             &through);
        org = leave_specular(org, hit, dir, ng, front, through, lift);
        weight *= carried;
        if (!(surface->kind == RAD_SPECULAR_THIN_GLASS && through)) {
            dir = next;
            break;
        }
        if (bounce + 1u == RAD_SPECULAR_BOUNCES) return; /* where shadow rays stop crossing panes */
        hit = trace_closest(&scene, org, dir);
    }
    const float3 amount = emitted * weight; /* below 2^32 quanta; a NaN converts to 0 */
    ulong on[3] = {convert_ulong_sat(amount.x), convert_ulong_sat(amount.y), convert_ulong_sat(amount.z)};
    if (on[0] == 0ul && on[1] == 0ul && on[2] == 0ul) return;
    hit = trace_closest(&scene, org, dir);
    uint passed;
    if (!follow_specular(&scene, elements, lift, rad_hash2(rayKey, RAD_SPECULAR_CHOICES), org, &hit, &dir, on, power,
                         &passed))
        return;
    const uint column = hit_element(&scene, elements, hit, dir, elementCount);
    volatile __global uint* sum = power + (size_t)column * 6u;
    for (int c = 0; c < 3; ++c) atomic_add_fixed(sum + 2 * c, on[c]);
    if (column < elementCount) {
        volatile __global uint* caustic = power + (size_t)(elementCount + 2u + column) * 6u;
        for (int c = 0; c < 3; ++c) atomic_add_fixed(caustic + 2 * c, on[c]);
    }
}
#endif

/* Rays a work group takes at a time when it keeps its own counters. */
#define RAD_RAYS_PER_TAKE 64u

/* The rays 0 .. rayCount - 1 of a launch deliver their power. `sets` sets of counters lie one
 * after another, `columns` x 6 words apart (elementCount + 2, and elementCount more with
 * specular transport); the gather adds them.
 *   takers == 0 (GPUs): work item g casts ray g, into the one set.
 *   takers > 0 (PoCL's CPU device: one per thread): the launch has `takers` work groups, and the
 *     first work item of group k takes rays RAD_RAYS_PER_TAKE at a time from `next` (0 before
 *     the launch) until none are left, adding into set k mod `sets`. Threads that add into one
 *     set pass its cache lines between their cores on nearly every ray; with a set each they
 *     do not (docs/results.md, "The whole solve on two threads").
 * The sums are integers either way: the result does not depend on who cast which ray. */
__kernel void shoot_power(RAD_KERNEL_PARAMS(RAD_SHOOT_POWER_KERNEL)) {
    const SceneData scene = RAD_SCENE_DATA;
    const float lift = scene.info->lift;
    if (takers == 0u) {
        const uint ray = get_global_id(0);
        if (ray < rayCount)
            deliver_ray(&scene, sources, sourceCount, ray, shooters, power, elements, elementCount, elementStart,
                        elementCdf, frames, lift);
        return;
    }
    if (get_local_id(0) != 0u) return;
    volatile __global uint* own = power + (size_t)(get_group_id(0) % sets) * columns * 6u;
    for (;;) {
        const uint first = atomic_add(next, RAD_RAYS_PER_TAKE);
        if (first >= rayCount) break;
        const uint end = min(first + RAD_RAYS_PER_TAKE, rayCount);
        for (uint ray = first; ray < end; ++ray)
            deliver_ray(&scene, sources, sourceCount, ray, shooters, own, elements, elementCount, elementStart,
                        elementCdf, frames, lift);
    }
}
