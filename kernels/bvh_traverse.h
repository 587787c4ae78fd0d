/* Closest-hit traversal of the 8-wide BVH (shared_types.h) with a watertight ray-triangle
 * test (Woop, Benthin and Wald, "Watertight Ray/Triangle Intersection", JCGT 2013): a ray
 * through an edge or vertex shared by two faces hits at least one of them, so closed scenes do
 * not leak. This holds only without FP contraction, which every kernel file turns off.
 * Alpha-masked faces (AlphaFace, shared_types.h) let rays through where their alpha is below
 * the cutoff, in every kernel that traces: shooting, shadow rays, the camera, the path tracer. */
#ifndef RADIOSITY_BVH_TRAVERSE_H
#define RADIOSITY_BVH_TRAVERSE_H

#include "scene_data.h"
#include "texture.h"

/* The traversal's inner calls are inlined by force: PoCL's LLVM kept intersect_leaf a call, so
 * the hit and the ray went through memory on every leaf. */
#ifdef __clang__
#define RAD_ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define RAD_ALWAYS_INLINE inline
#endif

typedef struct {
    float3 org;
    float3 dir;
    float3 invDir;  /* 1 / dir, with zero components replaced by tiny ones: no NaN in the slab test */
    int kx, ky, kz; /* axes after permuting the largest direction component to z */
    float sx, sy, sz;
    float okx, oky, okz; /* the origin's components along kx, ky, kz */
    int masks;           /* whether any face of the scene is alpha-masked */
} TraceRay;

typedef struct {
    float t;        /* distance along dir (dir is unit) */
    int face;       /* -1 when nothing was hit */
    float b1, b2;   /* barycentric weights of the face's v1 and v2 at the hit */
} Hit;

inline float component(float3 v, int axis) { return axis == 0 ? v.x : (axis == 1 ? v.y : v.z); }

inline float tiny_if_zero(float d) { return fabs(d) < 1e-30f ? copysign(1e-30f, d) : d; }

inline TraceRay make_trace_ray(float3 org, float3 dir) {
    TraceRay r;
    r.org = org;
    r.dir = dir;
    r.invDir = (float3)(1.0f / tiny_if_zero(dir.x), 1.0f / tiny_if_zero(dir.y), 1.0f / tiny_if_zero(dir.z));
    const float3 a = fabs(dir);
    r.kz = a.x > a.y ? (a.x > a.z ? 0 : 2) : (a.y > a.z ? 1 : 2);
    r.kx = r.kz == 2 ? 0 : r.kz + 1;
    r.ky = r.kx == 2 ? 0 : r.kx + 1;
    if (component(dir, r.kz) < 0.0f) { /* keep the winding: swap x and y */
        const int k = r.kx;
        r.kx = r.ky;
        r.ky = k;
    }
    const float dz = component(dir, r.kz);
    r.sx = component(dir, r.kx) / dz;
    r.sy = component(dir, r.ky) / dz;
    r.sz = 1.0f / dz;
    r.okx = component(org, r.kx);
    r.oky = component(org, r.ky);
    r.okz = component(org, r.kz);
    return r;
}

/* Whether the ray passes through face `face` at barycentric weights (b1, b2): an alpha-masked
 * face whose alpha there is below its cutoff. */
inline bool masked_out(const SceneGeometry* scene, int face, float b1, float b2) {
    const uint index = scene->faces[face].alpha;
    if (index == 0u) return false;
    __global const AlphaFace* a = &scene->alpha[index];
    float alpha = a->factor;
    if (a->slot >= 0) {
        const float b0 = 1.0f - b1 - b2;
        const float2 uv = b0 * vload2(0, a->uv) + b1 * vload2(1, a->uv) + b2 * vload2(2, a->uv);
        alpha *= sample_alpha(scene->texels, &scene->textureSlots[a->slot], uv);
    }
    return alpha < a->cutoff;
}

/* Tests the four faces of a leaf block at once and keeps the nearest hit closer than hit->t. */
RAD_ALWAYS_INLINE void intersect_leaf(const SceneGeometry* scene, __global const LeafBlock* block, const TraceRay* r,
                                      Hit* hit) {
    const float4 az = vload4(0, block->v[0][r->kz]) - r->okz;
    const float4 bz = vload4(0, block->v[1][r->kz]) - r->okz;
    const float4 cz = vload4(0, block->v[2][r->kz]) - r->okz;
    const float4 ax = vload4(0, block->v[0][r->kx]) - r->okx - r->sx * az;
    const float4 ay = vload4(0, block->v[0][r->ky]) - r->oky - r->sy * az;
    const float4 bx = vload4(0, block->v[1][r->kx]) - r->okx - r->sx * bz;
    const float4 by = vload4(0, block->v[1][r->ky]) - r->oky - r->sy * bz;
    const float4 cx = vload4(0, block->v[2][r->kx]) - r->okx - r->sx * cz;
    const float4 cy = vload4(0, block->v[2][r->ky]) - r->oky - r->sy * cz;
    /* Scaled barycentric weights of v0, v1, v2: signed areas seen along the ray. */
    const float4 u = cx * by - cy * bx;
    const float4 v = ax * cy - ay * cx;
    const float4 w = bx * ay - by * ax;
    const int4 outside = ((u < 0.0f) | (v < 0.0f) | (w < 0.0f)) & ((u > 0.0f) | (v > 0.0f) | (w > 0.0f));
    const float4 det = u + v + w;
    const float4 tScaled = u * (r->sz * az) + v * (r->sz * bz) + w * (r->sz * cz);
    /* Hit when det != 0, t > 0 (same sign as det) and t < hit->t, all without dividing. */
    const int4 sameSign = (as_int4(tScaled) ^ as_int4(det)) >= 0;
    const float4 absDet = fabs(det);
    const float4 absT = fabs(tScaled);
    const int4 valid = ~outside & (det != 0.0f) & sameSign & (absT > 0.0f) & (absT < hit->t * absDet) &
                       (vload4(0, block->face) >= 0);
    if (any(valid)) {
        float ts[4], vs[4], ws[4], dets[4];
        int oks[4];
        vstore4(absT / absDet, 0, ts);
        vstore4(v, 0, vs);
        vstore4(w, 0, ws);
        vstore4(det, 0, dets);
        vstore4(valid, 0, oks);
        for (int lane = 0; lane < 4; ++lane) {
            if (!(oks[lane] && ts[lane] < hit->t)) continue;
#ifdef RAD_ALPHA_MASKS
            if (r->masks && masked_out(scene, block->face[lane], vs[lane] / dets[lane], ws[lane] / dets[lane]))
                continue;
#endif
            hit->t = ts[lane];
            hit->face = block->face[lane];
            hit->b1 = vs[lane] / dets[lane];
            hit->b2 = ws[lane] / dets[lane];
        }
    }
}

/* The larger and smaller of each pair by comparison: defined for infinities, which the slab test
 * meets (hit.t before the first hit, empty slots' bounds), where OpenCL leaves max and min
 * undefined, and a single instruction on CPUs, where fmax and fmin also sort out NaNs. */
inline float8 larger8(float8 a, float8 b) { return select(b, a, a > b); }
inline float8 smaller8(float8 a, float8 b) { return select(b, a, a < b); }

/* Children whose boxes the ray enters are pushed nearest last, so they are popped nearest
 * first; entries farther than the nearest hit found meanwhile are dropped when popped. */
/* The nearest face along the ray closer than tmax (INFINITY: any), or hit.face == -1. */
inline Hit trace_within(const SceneGeometry* scene, float3 org, float3 dir, float tmax) {
    __global const BvhNode* nodes = scene->nodes;
    __global const LeafBlock* blocks = scene->blocks;
    TraceRay r = make_trace_ray(org, dir);
#ifdef RAD_ALPHA_MASKS /* built so only for scenes with masked faces (host/device/device_scene.h) */
    r.masks = scene->alpha[0].count > 0u;
#else
    r.masks = 0;
#endif
    Hit hit;
    hit.t = tmax;
    hit.face = -1;
    hit.b1 = 0.0f;
    hit.b2 = 0.0f;

    int stackNode[RAD_STACK_SIZE];
    float stackT[RAD_STACK_SIZE];
    int sp = 0;
    stackNode[sp] = 0;
    stackT[sp] = 0.0f;
    ++sp;
    /* The near and far planes of each slab follow from the signs of invDir, which the slab test
     * multiplies by: a component of -0.0 is not < 0, yet its tiny stand-in is negative, and
     * taking the sign from dir made such rays (an axis-aligned orthographic camera's) miss
     * everything. Kept as offsets, in floats within a node, of each axis's near and far bounds
     * (lo[3][8], then hi[3][8]), so a node's planes are not chosen again at every node. */
    const int nearX = r.invDir.x < 0.0f ? 24 : 0, nearY = r.invDir.y < 0.0f ? 32 : 8;
    const int nearZ = r.invDir.z < 0.0f ? 40 : 16;
    const int farX = 24 - nearX, farY = 40 - nearY, farZ = 56 - nearZ;

    while (sp > 0) {
        --sp;
        const int entry = stackNode[sp];
        if (stackT[sp] > hit.t) continue;
        if (entry < 0) {
            /* A leaf: a run of 1 to RAD_MAX_LEAF_BLOCKS blocks (host/bvh/wide_bvh.cpp). One block
             * per pass of this loop, the rest put back where the leaf was popped from, so it is
             * dropped like any entry once a hit nearer than its box is found. Not a loop here:
             * Mesa's llvmpipe lost hits in one (tests/test_emitters.cpp's
             * DeviceDirectLightAgreesWithTheHost), and writing the blocks out doubled its build
             * times. */
            const int count = RAD_LEAF_COUNT(entry);
            const uint first = RAD_LEAF_FIRST(entry);
            intersect_leaf(scene, &blocks[first], &r, &hit);
            if (count > 1) {
                stackNode[sp] = RAD_LEAF_LINK(first + 1u, (uint)count - 1u);
                ++sp; /* with the same stackT */
            }
            continue;
        }
        __global const BvhNode* node = &nodes[entry];
        __global const float* bounds = (__global const float*)node;
        const float8 tnx = (vload8(0, bounds + nearX) - r.org.x) * r.invDir.x;
        const float8 tny = (vload8(0, bounds + nearY) - r.org.y) * r.invDir.y;
        const float8 tnz = (vload8(0, bounds + nearZ) - r.org.z) * r.invDir.z;
        const float8 tfx = (vload8(0, bounds + farX) - r.org.x) * r.invDir.x;
        const float8 tfy = (vload8(0, bounds + farY) - r.org.y) * r.invDir.y;
        const float8 tfz = (vload8(0, bounds + farZ) - r.org.z) * r.invDir.z;
        const float8 tnear = larger8(larger8(tnx, tny), larger8(tnz, (float8)(0.0f)));
        /* Far distances grow by a few ulps (Ize 2013) so rounding never rejects a touching ray. */
        const float8 tfar = smaller8(smaller8(tfx, tfy), smaller8(tfz, (float8)(hit.t))) * 1.0000004f;
        const int8 enter = tnear <= tfar;
        if (!any(enter)) continue;
        float tn[8];
        int in[8];
        vstore8(tnear, 0, tn);
        vstore8(enter, 0, in);
        const int base = sp;
        for (int slot = 0; slot < 8; ++slot) {
            /* Empty slots' inverted bounds keep finite rays out; a NaN or infinite ray must not
             * follow them either. */
            if (!in[slot] || node->child[slot] == RAD_EMPTY_CHILD) continue;
            /* Insertion into the entries pushed for this node, keeping the nearest on top. */
            int pos = sp++;
            while (pos > base && stackT[pos - 1] < tn[slot]) {
                stackT[pos] = stackT[pos - 1];
                stackNode[pos] = stackNode[pos - 1];
                --pos;
            }
            stackT[pos] = tn[slot];
            stackNode[pos] = node->child[slot];
        }
    }
    return hit;
}

inline Hit trace_closest(const SceneGeometry* scene, float3 org, float3 dir) {
    return trace_within(scene, org, dir, INFINITY);
}

#endif
