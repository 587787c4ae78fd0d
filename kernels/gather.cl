/* Point-to-shooter gather form factors (after Wallace, Elmquist and Haines 1989): for shooter
 * patch i and receiver patch j, F_ji is the mean over three interior points of j (the
 * three-point Gauss rule for triangles, exact for quadratic variation) of the closed-form
 * factor from the point to the shooter triangle (polygon_factor.h) times the fraction of M
 * stratified shadow rays from the point to the shooter that nothing blocks. Interior points,
 * not j's corners: a corner can lie on the shooter's edge, where the point-to-polygon kernel is
 * singular. The row entry is F_ij = F_ji A_j / A_i (reciprocity), in 32-bit fixed point. One
 * work item per (shooter, receiver): no atomics; the cost grows with receivers, not with rays.
 * Where no face of the scene can lie between the two patches (shaft.h: none meets the convex
 * hull of the rays' ends), every shadow ray arrives and none is traced. */
#pragma OPENCL FP_CONTRACT OFF

#include "kernel_args.h"
#include "rng.h"
#include "sampling.h"
#include "vector_math.h"
#include "bvh_traverse.h"
#include "polygon_factor.h"
#include "shaft.h"

/* Barycentrics kept off the triangle's edges by its inset, as ray sources are (ray_source.h):
 * the triangle with corners (i, i), (1 - 2i, i), (i, 1 - 2i). A point on an edge, lifted along the
 * normal, stays on the plane of a neighbouring face at right angles to it, where rounding can
 * make a ray ending there hit that face; kept off the edges, the ends are clear of it by the
 * lift, and the shaft of the points can leave that face out. */
inline float2 inset_barycentrics(__global const SampleTriangle* t, float2 b) {
    const float inset = t->tangent[3];
    return b * (1.0f - 3.0f * inset) + inset;
}

/* The fraction of `rays` shadow rays from p (already lifted) to stratified points of the
 * shooter (lifted to its front, kept off its edges) that arrive unblocked. */
inline float visible_fraction(const SceneGeometry* scene, __global const SampleTriangle* shooter, float3 p, uint rays,
                              uint key) {
    const float3 v0 = vload3(0, shooter->v0), e1 = vload3(0, shooter->e1), e2 = vload3(0, shooter->e2);
    const float3 n = vload3(0, shooter->normal);
    uint open = 0u;
    for (uint r = 0u; r < rays; ++r) {
        const uint4 x = scrambled_sobol4(r, key);
        const float2 b = inset_barycentrics(shooter, triangle_barycentrics((float2)(unit_float(x.x), unit_float(x.y))));
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
    /* The shaft of the rays' ends: the receiver's three points and the corners of the part of
     * the shooter its points are drawn from (kept off its edges, lifted to its front). The
     * margin, RAD_SHAFT_ROUNDING of the farthest point's largest coordinate, is a quarter of the
     * lift a patch that far from the origin has (host/mesh/sampling_tables.h, originLift: 2^-19
     * of its largest coordinate): above the rounding of the planes' offsets, and below the lift
     * and inset that keep each patch's own face and its neighbours clear of the ends where both
     * patches lie at about the same distance from the origin (elsewhere they are kept, and the
     * rays traced). */
    bool open = true;
    if (seen) {
        const float3 sl = s->v0[3] * sn;
        const float2 c0 = inset_barycentrics(s, (float2)(0.0f, 0.0f)), c1 = inset_barycentrics(s, (float2)(1.0f, 0.0f));
        const float2 c2 = inset_barycentrics(s, (float2)(0.0f, 1.0f));
        const float3 ends[RAD_SHAFT_POINTS] = {p[0], p[1], p[2], sv0 + c0.x * se1 + c0.y * se2 + sl,
                                               sv0 + c1.x * se1 + c1.y * se2 + sl, sv0 + c2.x * se1 + c2.y * se2 + sl};
        float largest = 0.0f;
        for (int e = 0; e < RAD_SHAFT_POINTS; ++e)
            largest = fmax(largest, fmax(fmax(fabs(ends[e].x), fabs(ends[e].y)), fabs(ends[e].z)));
        const Shaft shaft = make_shaft(ends, RAD_SHAFT_ROUNDING * largest);
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
