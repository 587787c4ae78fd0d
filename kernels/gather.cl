/* Point-to-shooter gather form factors (after Wallace, Elmquist and Haines 1989): for shooter
 * patch i and receiver patch j, F_ji is the mean over three interior points of j (the
 * three-point Gauss rule for triangles, exact for quadratic variation) of the closed-form
 * factor from the point to the shooter triangle (polygon_factor.h) times the fraction of M
 * stratified shadow rays from the point to the shooter that nothing blocks. Interior points,
 * not j's corners: a corner can lie on the shooter's edge, where the point-to-polygon kernel is
 * singular. The row entry is F_ij = F_ji A_j / A_i (reciprocity), in 32-bit fixed point. One
 * work item per (shooter, receiver): no atomics; the cost grows with receivers, not with rays.
 * Where no face of the scene can lie between the two patches (shaft.h: none meets the convex
 * hull of both, lifted as the rays' ends are), every shadow ray arrives and none is traced: in
 * a convex room, all of them. */
#pragma OPENCL FP_CONTRACT OFF

#include "kernel_args.h"
#include "rng.h"
#include "sampling.h"
#include "vector_math.h"
#include "bvh_traverse.h"
#include "polygon_factor.h"
#include "shaft.h"

/* The fraction of `rays` shadow rays from p (already lifted) to stratified points of the
 * shooter (lifted to its front) that arrive unblocked. */
inline float visible_fraction(const SceneGeometry* scene, __global const SampleTriangle* shooter, float3 p, uint rays,
                              uint key) {
    const float3 v0 = vload3(0, shooter->v0), e1 = vload3(0, shooter->e1), e2 = vload3(0, shooter->e2);
    const float3 n = vload3(0, shooter->normal);
    uint open = 0u;
    for (uint r = 0u; r < rays; ++r) {
        const uint4 x = scrambled_sobol4(r, key);
        const float2 b = triangle_barycentrics((float2)(unit_float(x.x), unit_float(x.y)));
        const float3 q = v0 + b.x * e1 + b.y * e2 + shooter->v0[3] * n;
        const float3 d = q - p;
        const float distance = sqrt(dot3(d, d));
        if (!(distance > 0.0f)) continue;
        const Hit hit = trace_within(scene, p, d / distance, distance);
        if (hit.face < 0) ++open;
    }
    return (float)open / (float)rays;
}

__kernel void gather_rows(RAD_KERNEL_PARAMS(RAD_GATHER_ROWS_KERNEL)) {
    const uint gid = get_global_id(0);
    if (gid >= shooterCount * patchCount) return;
    const SceneGeometry scene = RAD_SCENE_GEOMETRY;
    const uint k = gid / patchCount, j = gid % patchCount, i = shooters[k];
    __global uint* out = &rows[(size_t)k * (patchCount + 1u) + j];
    __global const SampleTriangle* s = &triangles[i];
    __global const SampleTriangle* r = &triangles[j];
    const float3 sv0 = vload3(0, s->v0), se1 = vload3(0, s->e1), se2 = vload3(0, s->e2), sn = vload3(0, s->normal);
    const float3 rv0 = vload3(0, r->v0), re1 = vload3(0, r->e1), re2 = vload3(0, r->e2), rn = vload3(0, r->normal);
    if (i == j) {
        *out = 0u;
        return;
    }
    const float2 gauss[3] = {(float2)(1.0f / 6.0f, 1.0f / 6.0f), (float2)(2.0f / 3.0f, 1.0f / 6.0f),
                             (float2)(1.0f / 6.0f, 2.0f / 3.0f)};
    float3 p[3];
    float f[3];
    bool seen = false;
    for (int g = 0; g < 3; ++g) {
        p[g] = rv0 + gauss[g].x * re1 + gauss[g].y * re2 + r->v0[3] * rn;
        f[g] = point_to_triangle_factor(p[g], rn, sv0, sv0 + se1, sv0 + se2, sn);
        seen |= f[g] > 0.0f;
    }
    /* The shaft between the two patches as the rays' ends lie: each lifted to its front. Its
     * margin, a quarter of the lift, is far above the ray test's rounding and below the lift that
     * keeps the patches' own faces (and their neighbours in the plane) out of the shaft. */
    bool open = true;
    if (seen) {
        const float3 rl = r->v0[3] * rn, sl = s->v0[3] * sn;
        const float3 corners[RAD_SHAFT_POINTS] = {rv0 + rl, rv0 + re1 + rl, rv0 + re2 + rl,
                                                  sv0 + sl, sv0 + se1 + sl, sv0 + se2 + sl};
        const Shaft shaft = make_shaft(corners, 0.25f * fmin(r->v0[3], s->v0[3]));
        open = !shaft_may_be_blocked(&scene, &shaft);
    }
    float fji = 0.0f;
    for (int g = 0; g < 3; ++g) {
        if (f[g] > 0.0f) {
            const uint key = rad_hash2(rad_hash2(seed, i), j * 3u + (uint)g);
            fji += f[g] * (open ? 1.0f : visible_fraction(&scene, s, p[g], shadowRays, key));
        }
    }
    fji /= 3.0f;
    const float fij = fji * r->normal[3] / s->normal[3];
    /* Saturating: an estimate of F_ij can reach or pass 1 (it is clipped to 1 - 2^-32 here), and a
     * plain cast of 2^32 or more is undefined (progressive.cl). */
    *out = convert_uint_sat(fij * 4294967296.0f + 0.5f);
}
