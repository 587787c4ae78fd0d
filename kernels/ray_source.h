/* Where a ray starts and where it goes: a sample of a RaySource (shared_types.h) turned into a
 * point on one of its triangles and a cosine-distributed direction on the emitting side. */
#ifndef RADIOSITY_RAY_SOURCE_H
#define RADIOSITY_RAY_SOURCE_H

/* The source that launch-wide ray `ray` belongs to: the last one whose firstRay <= ray. */
inline uint find_source(__global const RaySource* sources, uint count, uint ray) {
    uint lo = 0u, hi = count;
    while (hi - lo > 1u) {
        const uint mid = (lo + hi) / 2u;
        if (sources[mid].firstRay <= ray) lo = mid;
        else hi = mid;
    }
    return lo;
}

/* Picks the triangle of the source that x falls on, in proportion to area: cdf[k] is the end
 * of triangle k's share of 2^32 within the run, found through the run's guide (pick_guided). */
inline uint pick_triangle(__global const uint* cdf, RaySource src, uint x, float* rescaled) {
    if (src.triangleCount <= 1u) {
        *rescaled = unit_float(x);
        return src.firstTriangle;
    }
    __global const uint* ends = cdf + src.firstTriangle;
    const uint k = pick_guided(ends, cdf + src.guide, src.triangleCount, x);
    *rescaled = within_share(ends, src.triangleCount, k, x);
    return src.firstTriangle + k;
}

typedef struct {
    float3 org;
    float3 dir;
} SourceRay;

/* The ray from the point with barycentrics `bary` (on e1, e2) of the triangle, in the
 * cosine-distributed direction that `u` picks. */
inline SourceRay source_ray_at(__global const SampleTriangle* tri, float2 bary, float2 u) {
    const float3 v0 = vload3(0, tri->v0);
    const float3 e1 = vload3(0, tri->e1);
    const float3 e2 = vload3(0, tri->e2);
    const float3 n = vload3(0, tri->normal);
    const float3 t = vload3(0, tri->tangent);
    const float3 b = cross3(n, t);
    /* Kept off the edges by the inset, as far as the lift below: rounding must not put an
     * origin beside a patch at a concave edge on the wrong side of the neighbouring face. */
    const float inset = tri->tangent[3];
    const float2 kept = bary * (1.0f - 3.0f * inset) + inset;
    const float3 w = cosine_hemisphere(u);
    SourceRay ray;
    /* Lifted off the patch by a few ulps of its coordinates, so it cannot hit its own face or a
     * coplanar neighbour, and starts inside a closed scene even next to its edges. */
    ray.org = v0 + kept.x * e1 + kept.y * e2 + tri->v0[3] * n;
    ray.dir = w.x * t + w.y * b + w.z * n;
    return ray;
}

/* A uniformly distributed point of the triangle (u.xy) and a direction (u.zw). */
inline SourceRay source_ray(__global const SampleTriangle* tri, float4 u) {
    return source_ray_at(tri, triangle_barycentrics(u.xy), u.zw);
}

#endif
