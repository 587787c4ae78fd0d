/* Rays on through mirrors, rough metals and glass (material.h): the one rule for how far a ray
 * continued from a surface leaves it, the one step every pass takes at such a surface (scatter,
 * then leave it on the side the ray goes to), and the one walk from a hit on through them to the
 * first surface they do not scatter, which the shots, the sky's and environment's direct light,
 * the radiosity camera and the camera pass's indirect light per element take. The path tracer
 * and the camera pass's paths take the step inside their own loops, where they also sample the
 * lights at rough metals (light_estimate.h). */
#ifndef RADIOSITY_SPECULAR_WALK_H
#define RADIOSITY_SPECULAR_WALK_H

#include "bvh_traverse.h"
#include "element_lookup.h"
#include "fixed_point.h"
#include "material.h"
#include "patch_lookup.h"

/* The most mirrors and glass surfaces the camera pass, the sky's rays and shadow rays follow in a
 * row (the shots follow more: RAD_SHOT_SPECULAR_BOUNCES). */
#define RAD_SPECULAR_BOUNCES 8u
/* The shots follow more, since what a shot drops is light lost (a lossless glass sphere of flat
 * faces in the white furnace kept 0.11 % of the light it met at 8, 0.04 % at 32:
 * tests/test_specular_transport.cpp). */
#define RAD_SHOT_SPECULAR_BOUNCES 32u

/* How far a ray continued from the point p it reached from `origin` leaves the surface: more
 * than the hit point's rounding (32 ulps of the larger coordinate of the two) and at least
 * `lift`, so the new ray cannot find the face it leaves. */
inline float ray_offset(float3 origin, float3 p, float lift) {
    return fmax(lift, fmax(max_abs3(origin), max_abs3(p)) * 0x1p-18f);
}

/* Where a ray from `org` along dir that met a surface at `hit` (front normal ng, met from the
 * front when `front`) goes on from: off the surface by ray_offset, on the side it leaves to (the
 * other one when it passed `through`). */
inline float3 leave_surface(float3 org, Hit hit, float3 dir, float3 ng, bool front, bool through, float lift) {
    const float3 p = org + hit.t * dir;
    const float off = ray_offset(org, p, lift);
    return p + ((front != through) ? off : -off) * ng;
}

/* The step at a mirror, rough metal or glass: a ray from *org along dir that hit it at `hit`
 * goes on in the direction returned, drawn with u (material_scatter), from *org moved off the
 * surface to the side it leaves to; *carried: what the surface passes on per channel;
 * *through: whether it passed to the other side; forward: the ray carries light (a shot's). */
inline float3 specular_step(const SceneData* scene, Hit hit, float3 dir, float3 u, float lift, bool forward,
                            float3* org, float3* carried, bool* through) {
    const float3 ng = vload3(0, scene->geometry.faces[hit.face].normal);
    const bool front = dot3(dir, ng) < 0.0f;
    const float3 next = material_scatter(scene, hit, dir, ng, u, forward, carried, through);
    *org = leave_surface(*org, hit, dir, ng, front, *through, lift);
    return next;
}

/* A ray on its walk: from origin along dir, meeting `hit` first (face -1: nothing). weight: what
 * the surfaces passed so far pass on, per channel; glow: what they emit themselves (from sides
 * with patches), as weighed; passed: how many. */
typedef struct {
    float3 origin, dir;
    Hit hit;
    float3 weight, glow;
    uint passed;
} SpecularWalk;

inline SpecularWalk specular_walk_from(const SceneData* scene, float3 origin, float3 dir) {
    SpecularWalk w;
    w.origin = origin;
    w.dir = dir;
    w.hit = trace_closest(&scene->geometry, origin, dir);
    w.weight = (float3)(1.0f);
    w.glow = (float3)(0.0f);
    w.passed = 0u;
    return w;
}

/* The power a shot's ray carries (kernels/shoot.cl), in 64-bit fixed point per channel, and the
 * counters and element trees where each surface it passes leaves the part it keeps. */
typedef struct {
    ulong carried[3];
    volatile __global uint* power;
    __global const ElementNode* elements;
    __global uint* touched; /* the blocks of elements that received (shared_types.h), or 0 */
} ShotPower;

/* The element at a hit on the side `front` of its face, or where that side has no patches (a
 * single-sided face's back), on the other side. */
inline uint element_on_side(const SceneGeometry* scene, __global const ElementNode* elements, Hit hit, bool front) {
    __global const FaceInfo* face = &scene->faces[hit.face];
    if ((front ? face->frontPatch : face->backPatch) == RAD_NO_PATCH) front = !front;
    const uint first = front ? face->frontPatch : face->backPatch;
    const GridPoint g = grid_locate(face->subdivision, hit.b1, hit.b2);
    float3 w = front ? g.weights : g.weights.xzy; /* a back patch lists its corners 0, 2, 1 */
    return locate_element(elements, first + g.index, &w);
}

/* How a walk ended. */
#define RAD_WALK_SURFACE 0u /* at a surface the walk does not pass (a diffuse one): w->hit */
#define RAD_WALK_OUTSIDE 1u /* it left the scene */
#define RAD_WALK_BLACK 2u   /* at the black side of an opaque surface (material_black_side): w->hit */
#define RAD_WALK_ENDED 3u   /* `limit` surfaces passed, or nothing passed on */

/* Follows w through mirrors, rough metals and glass from its hit, each choice drawn from
 * specular_choice(key, k) for the k-th surface, each new ray leaving its surface by at least
 * `lift`, until it meets a surface they do not scatter, leaves the scene, or meets the side of an
 * opaque one without patches (its weight then 0), or reaches surface number `limit` (weight 0).
 * glow: add what the surfaces met emit. shot: the ray carries a shot's power (else null), of
 * which each surface keeps its part (1 - what it passes on, in fixed point, so no power is made
 * or lost, and the sums stay exact and independent of the order of the rays), the surface at
 * the limit all of it; the walk ends when nothing is left to carry. */
inline uint walk_specular(const SceneData* scene, SpecularWalk* w, uint limit, uint key, float lift, bool glow,
                          ShotPower* shot) {
    for (uint k = 0u;; ++k) {
        if (w->hit.face < 0) return RAD_WALK_OUTSIDE;
        const uint kind = material_kind(scene, w->hit.face);
        if (material_is_diffuse(kind)) return RAD_WALK_SURFACE;
        __global const FaceInfo* face = &scene->geometry.faces[w->hit.face];
        const bool front = dot3(w->dir, vload3(0, face->normal)) < 0.0f;
        const bool patched = (front ? face->frontPatch : face->backPatch) != RAD_NO_PATCH;
        if (glow && patched) w->glow += w->weight * vload3(0, scene->faceMaterials[w->hit.face].emission);
        if (material_black_side(kind, patched)) {
            w->weight = (float3)(0.0f);
            return RAD_WALK_BLACK;
        }
        float3 carried = (float3)(0.0f); /* at the limit: nothing goes on */
        float3 next = w->dir;
        if (k < limit) {
            bool through;
            next = specular_step(scene, w->hit, w->dir, specular_choice(key, k), lift, shot != 0, &w->origin, &carried,
                                 &through);
        }
        if (shot != 0) {
            const uint element = element_on_side(&scene->geometry, shot->elements, w->hit, front);
            if (shot->touched != 0) shot->touched[element >> RAD_TOUCHED_SHIFT] = 1u;
            volatile __global uint* sum = shot->power + (size_t)element * 6u;
            const float passes[3] = {carried.x, carried.y, carried.z};
            for (int c = 0; c < 3; ++c) {
                const ulong on = fixed_part(shot->carried[c], passes[c]);
                atomic_add_fixed(sum + 2 * c, shot->carried[c] - on);
                shot->carried[c] = on;
            }
            if (shot->carried[0] == 0ul && shot->carried[1] == 0ul && shot->carried[2] == 0ul) return RAD_WALK_ENDED;
        }
        w->weight *= carried;
        if (!(k < limit)) return RAD_WALK_ENDED;
        w->dir = next;
        w->hit = trace_closest(&scene->geometry, w->origin, next);
        ++w->passed;
    }
}

#endif
