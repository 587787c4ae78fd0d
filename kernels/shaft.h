/* Shaft culling (after Haines and Wallace, "Shaft culling for efficient ray-traced radiosity",
 * 1991): every segment between two convex sets lies in the convex hull of their union, so a face
 * outside that hull blocks none of them, and where no face of the scene can lie inside it, every
 * shadow ray between the two sets arrives without tracing one. The hull here is bounded by its
 * box and by the planes through three of its points that leave all of them on one side (its
 * faces), and a face also by its own plane where all the points lie beyond it; a BVH node or a
 * face is outside when it lies wholly beyond one of them by more than a margin. The test is
 * conservative: a face it keeps may still block nothing, and the caller then traces its rays as
 * before. Every plane's offset is the extreme of the points (or of the face's corners) along its
 * own normal, as computed, so rounding in a normal only makes the test cull less; what it culls
 * lies beyond the margin from every segment between the points, up to the rounding of the
 * offsets themselves, which the caller's margin must exceed. */
#ifndef RADIOSITY_SHAFT_H
#define RADIOSITY_SHAFT_H

#include "bvh_traverse.h"
#include "scene_data.h"
#include "vector_math.h"

#define RAD_SHAFT_POINTS 6
/* The hull of six points has at most eight triangular faces; a few more hold near-duplicates
 * that rounding keeps apart. Fewer planes only cull less. */
#define RAD_SHAFT_MAX_PLANES 12

typedef struct {
    float3 lo, hi;                        /* the hull's box, widened by the margin */
    float4 plane[RAD_SHAFT_MAX_PLANES];   /* xyz: unit outward normal; w: the points' extreme along it */
    int planes;
    float3 point[RAD_SHAFT_POINTS];       /* the six points, for a face's own plane */
    float margin;                         /* metres; what lies nearer is kept */
} Shaft;

/* The rounding a plane test can make at coordinates up to `largest`: 2^-21 of it, some 8 ulps,
 * as the caller's margin is at the points' coordinates. A face or box farther from the origin
 * than the points is kept within its own, larger, tolerance. */
#define RAD_SHAFT_ROUNDING 0x1p-21f

/* The shaft of six points (gather.cl: the ends of its shadow rays), with a margin in metres. */
inline Shaft make_shaft(const float3* p, float margin) {
    Shaft s;
    s.lo = s.hi = p[0];
    for (int k = 1; k < RAD_SHAFT_POINTS; ++k) {
        s.lo = fmin(s.lo, p[k]);
        s.hi = fmax(s.hi, p[k]);
    }
    s.lo -= (float3)(margin);
    s.hi += (float3)(margin);
    s.planes = 0;
    for (int k = 0; k < RAD_SHAFT_POINTS; ++k) s.point[k] = p[k];
    s.margin = margin;
    for (int a = 0; a < RAD_SHAFT_POINTS - 2; ++a)
        for (int b = a + 1; b < RAD_SHAFT_POINTS - 1; ++b)
            for (int c = b + 1; c < RAD_SHAFT_POINTS; ++c) {
                const float3 m = cross3(p[b] - p[a], p[c] - p[a]);
                const float len = sqrt(dot3(m, m));
                if (!(len > 0.0f)) continue; /* collinear */
                const float3 n = m / len;
                float lo = dot3(n, p[0]), hi = lo;
                for (int k = 1; k < RAD_SHAFT_POINTS; ++k) {
                    const float d = dot3(n, p[k]);
                    lo = fmin(lo, d);
                    hi = fmax(hi, d);
                }
                /* Any direction bounds the hull between lo and hi; only the hull's faces (the
                 * triple on one of the two) bound it tightly. Offsets are the extremes
                 * themselves, so a plane never cuts the hull whatever the rounding. A triple
                 * within the margin of both extremes (a flat hull: coplanar points) gives its
                 * upper side only, and no edge planes are formed for it: that culls less, never
                 * wrongly. */
                const float at = dot3(n, p[a]);
                float4 plane;
                if (hi - at <= margin) plane = (float4)(n, hi);
                else if (at - lo <= margin) plane = (float4)(-n, -lo);
                else continue;
                bool known = false;
                for (int q = 0; q < s.planes; ++q)
                    if (dot3(s.plane[q].xyz, plane.xyz) > 0.99999f) known = true;
                if (!known && s.planes < RAD_SHAFT_MAX_PLANES) s.plane[s.planes++] = plane;
            }
    return s;
}

/* Whether a BVH node's eight children's boxes may meet the shaft. */
RAD_ALWAYS_INLINE int8 shaft_meets_boxes(const Shaft* s, __global const BvhNode* node) {
    __global const float* bounds = (__global const float*)node;
    const float8 lx = vload8(0, bounds), ly = vload8(0, bounds + 8), lz = vload8(0, bounds + 16);
    const float8 hx = vload8(0, bounds + 24), hy = vload8(0, bounds + 32), hz = vload8(0, bounds + 40);
    /* Empty slots' inverted bounds (+inf below, -inf above) fail the box test. */
    int8 meets = (lx <= s->hi.x) & (hx >= s->lo.x) & (ly <= s->hi.y) & (hy >= s->lo.y) & (lz <= s->hi.z) &
                 (hz >= s->lo.z);
    if (!any(meets)) return meets;
    const float8 largest = fmax(fmax(fmax(fabs(lx), fabs(hx)), fmax(fabs(ly), fabs(hy))), fmax(fabs(lz), fabs(hz)));
    const float8 tolerance = fmax((float8)(s->margin), RAD_SHAFT_ROUNDING * largest);
    for (int q = 0; q < s->planes && any(meets); ++q) {
        const float4 n = s->plane[q];
        /* The box's corner deepest along the normal. */
        const float8 nearest = n.x * (n.x > 0.0f ? lx : hx) + n.y * (n.y > 0.0f ? ly : hy) +
                               n.z * (n.z > 0.0f ? lz : hz);
        meets &= nearest <= n.w + tolerance;
    }
    return meets;
}

/* Whether any of a leaf block's four faces may meet the shaft. */
RAD_ALWAYS_INLINE bool shaft_meets_block(const Shaft* s, __global const LeafBlock* block) {
    float4 x[3], y[3], z[3];
    for (int v = 0; v < 3; ++v) {
        x[v] = vload4(0, block->v[v][0]);
        y[v] = vload4(0, block->v[v][1]);
        z[v] = vload4(0, block->v[v][2]);
    }
    int4 meets = vload4(0, block->face) >= 0;
    meets &= (fmin(fmin(x[0], x[1]), x[2]) <= s->hi.x) & (fmax(fmax(x[0], x[1]), x[2]) >= s->lo.x);
    meets &= (fmin(fmin(y[0], y[1]), y[2]) <= s->hi.y) & (fmax(fmax(y[0], y[1]), y[2]) >= s->lo.y);
    meets &= (fmin(fmin(z[0], z[1]), z[2]) <= s->hi.z) & (fmax(fmax(z[0], z[1]), z[2]) >= s->lo.z);
    if (!any(meets)) return false;
    float4 largest = (float4)(0.0f);
    for (int v = 0; v < 3; ++v) largest = fmax(largest, fmax(fmax(fabs(x[v]), fabs(y[v])), fabs(z[v])));
    const float4 tolerance = fmax((float4)(s->margin), RAD_SHAFT_ROUNDING * largest);
    for (int q = 0; q < s->planes && any(meets); ++q) {
        const float4 n = s->plane[q];
        int4 beyond = (int4)(-1);
        for (int v = 0; v < 3; ++v) beyond &= n.x * x[v] + n.y * y[v] + n.z * z[v] > n.w + tolerance;
        meets &= ~beyond;
    }
    if (!any(meets)) return false;
    /* A face's own plane, where all six points lie beyond it on one side. The normal, a cross
     * product in floats, is off by an angle that grows as the face is thin, so the face's own
     * corners are measured along it too and the plane taken at their extremes, as the hull's
     * planes are at the points'. A face of no area (a zero normal) is never culled so. */
    const float4 ux = x[1] - x[0], uy = y[1] - y[0], uz = z[1] - z[0];
    const float4 vx = x[2] - x[0], vy = y[2] - y[0], vz = z[2] - z[0];
    const float4 nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
    const float4 reach = tolerance * sqrt(nx * nx + ny * ny + nz * nz);
    const float4 e1 = nx * ux + ny * uy + nz * uz, e2 = nx * vx + ny * vy + nz * vz;
    const float4 top = fmax(fmax(e1, e2), (float4)(0.0f)) + reach, bottom = fmin(fmin(e1, e2), (float4)(0.0f)) - reach;
    int4 above = (int4)(-1), below = (int4)(-1);
    for (int k = 0; k < RAD_SHAFT_POINTS; ++k) {
        const float4 d = nx * (s->point[k].x - x[0]) + ny * (s->point[k].y - y[0]) + nz * (s->point[k].z - z[0]);
        above &= d > top;
        below &= d < bottom;
    }
    meets &= ~(above | below);
    return any(meets);
}

/* Whether any face of the scene may meet the shaft: if not, nothing blocks a segment inside it. */
inline bool shaft_may_be_blocked(const SceneGeometry* scene, const Shaft* s) {
    int stack[RAD_STACK_SIZE];
    int sp = 0;
    stack[sp++] = 0;
    while (sp > 0) {
        const int entry = stack[--sp];
        if (entry < 0) {
            /* One block per pass, the rest of the leaf put back, as the traversal does. */
            const int count = RAD_LEAF_COUNT(entry);
            const uint first = RAD_LEAF_FIRST(entry);
            if (shaft_meets_block(s, &scene->blocks[first])) return true;
            if (count > 1) stack[sp++] = RAD_LEAF_LINK(first + 1u, (uint)count - 1u);
            continue;
        }
        __global const BvhNode* node = &scene->nodes[entry];
        int in[8];
        vstore8(shaft_meets_boxes(s, node), 0, in);
        for (int slot = 0; slot < 8; ++slot)
            if (in[slot] && node->child[slot] != RAD_EMPTY_CHILD) stack[sp++] = node->child[slot];
    }
    return false;
}

#endif
