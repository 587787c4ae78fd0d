/* Ray shooting. Each work item casts one ray of one source (shared_types.h) and finds the
 * column it lands in: the patch (or, for power, the element) hit, or the count of those when it
 * leaves the scene, or one more when it hits the black back of a single-sided face. Rays from a patch are spread uniformly
 * over it and cosine-distributed, so the share of rays landing on j estimates the form factor
 * F_ij. Two kernels: `shoot` counts rays per source row (view factors: the geometry's, every
 * face opaque), `shoot_power` adds each ray's power (progressive refinement), carried on through
 * mirrors and glass where the scene has them (walk_specular, specular_walk.h). Integer sums make both independent of the order
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
#include "specular_walk.h"

/* Keys the random choices of rays that meet glass (a shooter's scramble is keyed otherwise). */
#define RAD_SPECULAR_CHOICES 0x7f4a7c15u

/* The column a hit is counted in. */
inline uint hit_column(const SceneGeometry* scene, Hit hit, float3 dir, uint patchCount) {
    if (hit.face < 0) return patchCount;
    __global const FaceInfo* face = &scene->faces[hit.face];
    const bool front = dot3(dir, vload3(0, face->normal)) < 0.0f;
    const uint first = front ? face->frontPatch : face->backPatch;
    if (first == RAD_NO_PATCH) return patchCount + 1u;
    return first + grid_cell_index(face->subdivision, hit.b1, hit.b2);
}

/* The element a hit lands on (via its patch's quadtree), or elementCount when the ray left
 * the scene, or elementCount + 1 on a black back. */
inline uint hit_element(const SceneGeometry* scene, __global const ElementNode* elements, Hit hit, float3 dir,
                        uint elementCount) {
    if (hit.face < 0) return elementCount;
    __global const FaceInfo* face = &scene->faces[hit.face];
    const bool front = dot3(dir, vload3(0, face->normal)) < 0.0f;
    if ((front ? face->frontPatch : face->backPatch) == RAD_NO_PATCH) return elementCount + 1u;
    return element_on_side(scene, elements, hit, front);
}

/* Casts ray `ray` of the launch; returns its hit and direction, and its source. */
inline Hit cast(const SceneGeometry* scene, __global const RaySource* sources, uint sourceCount, uint ray,
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
inline uint cast_ray(const SceneGeometry* scene, __global const RaySource* sources, uint sourceCount, uint ray,
                     uint patchCount, RaySource* source) {
    float3 dir;
    const Hit hit = cast(scene, sources, sourceCount, ray, source, &dir);
    return hit_column(scene, hit, dir, patchCount);
}

/* counts[row * (patchCount + 2) + column] += 1 for every ray. */
__kernel void shoot(RAD_KERNEL_PARAMS(RAD_SHOOT_KERNEL)) {
    const uint ray = get_global_id(0);
    if (ray >= rayCount) return;
    const SceneGeometry scene = RAD_SCENE_GEOMETRY;
    RaySource src;
    const uint column = cast_ray(&scene, sources, sourceCount, ray, patchCount, &src);
    atomic_inc(&counts[(size_t)src.row * (patchCount + 2u) + column]);
}

/* Casts ray `ray` of a launch of shooters: its origin on the shooter's patch is drawn element by
 * element, in proportion to the unshot power each holds (elementCdf, prepared for the batch by
 * progressive.cl's prepare_shooters), then uniformly within the element. A patch shoots its
 * elements' own distribution of light, not their average: receivers finer than shooters are
 * also finer sources. */
inline Hit cast_from_elements(const SceneGeometry* scene, __global const RaySource* sources, uint sourceCount, uint ray,
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

/* What one ray leaves where its walk ends: `carried` in the column of the element it lands on
 * (elementCount: it left the scene; + 1: a black back), and, when it came by way of mirrors or
 * glass (`caustic`), once more in that element's caustic column. */
typedef struct {
    ulong carried[3];
    uint column, caustic;
} Delivery;

/* Adds a delivery into the counters `power`: by atomics, or where no other work item adds into
 * them during the launch (`owned`), by plain additions, which a CPU overlaps with one another
 * where an atomic holds back everything after it until its cache line comes. The same sums. */
inline void deliver(const Delivery* d, volatile __global uint* power, uint elementCount, bool owned) {
    const uint times = d->caustic != 0u && d->column < elementCount ? 2u : 1u;
    for (uint k = 0u; k < times; ++k) {
        const size_t column = k == 0u ? (size_t)d->column : (size_t)(elementCount + 2u + d->column);
        volatile __global uint* sum = power + column * 6u;
        for (int c = 0; c < 3; ++c) {
            if (d->carried[c] == 0ul) continue;
            if (owned) add64((__global uint*)(sum + 2 * c), (uint)d->carried[c], (uint)(d->carried[c] >> 32));
            else atomic_add_fixed(sum + 2 * c, d->carried[c]);
        }
    }
}

/* Ray `ray`'s delivery (*out; false: it leaves nothing): its power per channel, in 64-bit fixed
 * point, for the element it lands on, and where it passed mirrors or glass on the way, for that
 * element's caustic column too (elementCount + 2 + e: the light that arrives there by specular
 * paths, the solution's caustic irradiance, which the camera pass reads apart;
 * kernels/view_pass.cl). The source's row names its Shooter, whose patch is its only triangle.
 * Marks the element's block in `touched` (where given). */
inline bool deliver_ray(const SceneData* scene, __global const RaySource* sources, uint sourceCount, uint ray,
                        __global const Shooter* shooters, volatile __global uint* power,
                        __global const ElementNode* elements, uint elementCount, __global const uint* elementStart,
                        __global const uint* elementCdf, __global const float4* frames, float lift,
                        __global uint* touched, Delivery* out) {
    RaySource src;
    float3 org, dir;
    Hit hit = cast_from_elements(&scene->geometry, sources, sourceCount, ray, shooters, elementStart, elementCdf,
                                 frames, &src, &org, &dir);
    __global const uint* w = shooters[src.row].weight;
    for (int c = 0; c < 3; ++c) out->carried[c] = fixed_value(w[2 * c], w[2 * c + 1]);
    out->caustic = 0u;
#ifdef RAD_SPECULAR_TRANSPORT
    /* Through mirrors and glass (Sillion and Puech's extended form factors, one ray at a time):
     * each surface on the way keeps its part of the power (specular_walk.h), whose diffuse
     * reflectance in the radiosity pass is 0 (progressive_solver.cpp), so that part counts as
     * absorbed. */
    ShotPower shot;
    for (int c = 0; c < 3; ++c) shot.carried[c] = out->carried[c];
    shot.power = power;
    shot.elements = elements;
    shot.touched = touched;
    SpecularWalk walk = {org, dir, hit, (float3)(1.0f), (float3)(0.0f), 0u};
    const uint key = rad_hash2(src.scramble ^ RAD_SPECULAR_CHOICES, src.firstSample + (ray - src.firstRay));
    if (walk_specular(scene, &walk, RAD_SHOT_SPECULAR_BOUNCES, key, lift, false, &shot) == RAD_WALK_ENDED)
        return false;
    for (int c = 0; c < 3; ++c) out->carried[c] = shot.carried[c];
    out->caustic = walk.passed > 0u ? 1u : 0u;
    hit = walk.hit;
    dir = walk.dir;
#endif
    out->column = hit_element(&scene->geometry, elements, hit, dir, elementCount);
    if (touched != 0 && out->column < elementCount) touched[out->column >> RAD_TOUCHED_SHIFT] = 1u;
    return true;
}

#ifdef RAD_SPECULAR_TRANSPORT
/* What punctual lights send by way of mirrors and glass, which no shadow ray can find (a point
 * light's image in a mirror, the focus of a lens): ray r of rays[3r .. 3r + 2] (origin, unit
 * direction, power per channel in quanta, below 2^32; host/solver/punctual_caustics.cpp draws them
 * from the lights by power) goes from its light to what it meets first. Where that is no mirror or glass, the
 * elements' direct light (direct_light.cl) has it, and the ray ends; so it does where it crosses a
 * thin pane straight on (shadow rays cross panes: shadow_ray.h), and goes on as before. At the
 * first surface that reflects or refracts it, the surface keeps its share, which the direct
 * light also counted (light_tree.h: receiver_keeps), and the ray goes on with the rest as the
 * shots' rays do (walk_specular, specular_walk.h), each surface after keeping its own share, to the element
 * it lands on: power (the shots' columns, one set, in quanta), in its column and once more in
 * its caustic column. */
__kernel void light_caustics(RAD_KERNEL_PARAMS(RAD_LIGHT_CAUSTICS_KERNEL)) {
    const uint r = get_global_id(0);
    if (r >= rayCount) return;
    const SceneData scene = RAD_SCENE_DATA;
    const float lift = scene.about.lift;
    float3 org = rays[3u * (size_t)r].xyz, dir = rays[3u * (size_t)r + 1u].xyz;
    const float3 emitted = rays[3u * (size_t)r + 2u].xyz;
    const uint rayKey = rad_hash2(key, r);
    float3 weight = (float3)(1.0f);
    Hit hit = trace_closest(&scene.geometry, org, dir);
    /* Straight through thin panes, as shadow rays go, to the first surface that turns it. */
    for (uint bounce = 0u;; ++bounce) {
        if (hit.face < 0 || bounce == RAD_SHOT_SPECULAR_BOUNCES) return;
        const uint kind = material_kind(&scene, hit.face);
        if (material_is_diffuse(kind)) return;
        __global const FaceInfo* face = &scene.geometry.faces[hit.face];
        const bool front = dot3(dir, vload3(0, face->normal)) < 0.0f;
        if (material_black_side(kind, (front ? face->frontPatch : face->backPatch) != RAD_NO_PATCH)) return;
        float3 carried;
        bool through;
        const float3 next =
            specular_step(&scene, hit, dir, specular_choice(rayKey, bounce), lift, true, &org, &carried, &through);
        weight *= carried;
        if (!(material_crossed_by_shadow_rays(kind) && through)) {
            dir = next;
            break;
        }
        if (bounce + 1u == RAD_SPECULAR_BOUNCES) return; /* where shadow rays stop crossing panes */
        hit = trace_closest(&scene.geometry, org, dir);
    }
    const float3 amount = emitted * weight; /* below 2^32 quanta; a NaN converts to 0 */
    ShotPower shot;
    shot.carried[0] = convert_ulong_sat(amount.x);
    shot.carried[1] = convert_ulong_sat(amount.y);
    shot.carried[2] = convert_ulong_sat(amount.z);
    if (shot.carried[0] == 0ul && shot.carried[1] == 0ul && shot.carried[2] == 0ul) return;
    shot.power = power;
    shot.elements = elements;
    shot.touched = 0; /* its counters are the host's to read, not the gather's */
    SpecularWalk walk = specular_walk_from(&scene, org, dir);
    if (walk_specular(&scene, &walk, RAD_SHOT_SPECULAR_BOUNCES, rad_hash2(rayKey, RAD_SPECULAR_CHOICES), lift, false,
                      &shot) == RAD_WALK_ENDED)
        return;
    Delivery d;
    for (int c = 0; c < 3; ++c) d.carried[c] = shot.carried[c];
    d.column = hit_element(&scene.geometry, elements, walk.hit, walk.dir, elementCount);
    d.caustic = 1u;
    deliver(&d, power, elementCount, false);
}
#endif

/* Rays a work group takes at a time when it keeps its own counters. */
#define RAD_RAYS_PER_TAKE 64u
/* Deliveries such a work group keeps before it adds them. */
#define RAD_DELIVERIES_KEPT 16u

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
    const float lift = scene.about.lift;
    Delivery d;
    if (takers == 0u) {
        const uint ray = get_global_id(0);
        if (ray < rayCount && deliver_ray(&scene, sources, sourceCount, ray, shooters, power, elements, elementCount,
                                          elementStart, elementCdf, frames, lift, touched, &d))
            deliver(&d, power, elementCount, false);
        return;
    }
    if (get_local_id(0) != 0u) return;
    volatile __global uint* own = power + (size_t)(get_group_id(0) % sets) * columns * 6u;
    /* With a set per taker its sums are this work item's alone: deliveries are kept, a few at a
     * time, and added together by plain additions whose cache misses overlap (a few are enough
     * for the misses a core has in flight at once). */
    const bool owned = sets == takers;
    Delivery kept[RAD_DELIVERIES_KEPT];
    uint count = 0u;
    for (;;) {
        const uint first = atomic_add(next, RAD_RAYS_PER_TAKE);
        if (first >= rayCount) break;
        const uint end = min(first + RAD_RAYS_PER_TAKE, rayCount);
        for (uint ray = first; ray < end; ++ray) {
            if (deliver_ray(&scene, sources, sourceCount, ray, shooters, own, elements, elementCount, elementStart,
                            elementCdf, frames, lift, touched, &kept[count]))
                ++count;
            if (count == RAD_DELIVERIES_KEPT) {
                for (uint k = 0u; k < count; ++k) deliver(&kept[k], own, elementCount, owned);
                count = 0u;
            }
        }
    }
    for (uint k = 0u; k < count; ++k) deliver(&kept[k], own, elementCount, owned);
}
