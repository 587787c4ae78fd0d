/* Ray shooting. Each work item casts one ray of one source (shared_types.h) and finds the
 * column it lands in: the patch hit, or patchCount when it leaves the scene, or patchCount + 1
 * when it hits the black back of a single-sided face. Rays from a patch are spread uniformly
 * over it and cosine-distributed, so the share of rays landing on j estimates the form factor
 * F_ij. Two kernels: `shoot` counts rays per source row (view factors), `shoot_power` adds
 * each ray's power (progressive refinement). Integer sums make both independent of the order
 * in which work items run. */
#pragma OPENCL FP_CONTRACT OFF

#include "shared_types.h"
#include "rng.h"
#include "sampling.h"
#include "vector_math.h"
#include "bvh_traverse.h"
#include "patch_lookup.h"
#include "ray_source.h"
#include "fixed_point.h"

/* The column a hit is counted in. */
inline uint hit_column(__global const FaceInfo* faces, Hit hit, float3 dir, uint patchCount) {
    if (hit.face < 0) return patchCount;
    __global const FaceInfo* face = &faces[hit.face];
    const bool front = dot3(dir, vload3(0, face->normal)) < 0.0f;
    const uint first = front ? face->frontPatch : face->backPatch;
    if (first == RAD_NO_PATCH) return patchCount + 1u;
    return first + grid_cell_index(face->subdivision, hit.b1, hit.b2);
}

/* Casts ray `ray` of the launch; returns its column and its source. */
inline uint cast_ray(__global const BvhNode* nodes, __global const LeafBlock* blocks, __global const FaceInfo* faces,
                     __global const SampleTriangle* triangles, __global const uint* cdf,
                     __global const RaySource* sources, uint sourceCount, uint ray, uint patchCount,
                     RaySource* source) {
    const RaySource src = sources[find_source(sources, sourceCount, ray)];
    const uint4 x = scrambled_sobol4(src.firstSample + (ray - src.firstRay), src.scramble);
    float u0;
    const uint triangle = pick_triangle(cdf, src, x.x, &u0);
    const float4 u = (float4)(u0, unit_float(x.y), unit_float(x.z), unit_float(x.w));
    const SourceRay r = source_ray(&triangles[triangle], u);
    const Hit hit = trace_closest(nodes, blocks, r.org, r.dir);
    *source = src;
    return hit_column(faces, hit, r.dir, patchCount);
}

/* counts[row * (patchCount + 2) + column] += 1 for every ray. */
__kernel void shoot(__global const BvhNode* nodes, __global const LeafBlock* blocks, __global const FaceInfo* faces,
                    __global const SampleTriangle* triangles, __global const uint* cdf,
                    __global const RaySource* sources, uint sourceCount, uint rayCount, uint patchCount,
                    __global uint* counts) {
    const uint ray = get_global_id(0);
    if (ray >= rayCount) return;
    RaySource src;
    const uint column = cast_ray(nodes, blocks, faces, triangles, cdf, sources, sourceCount, ray, patchCount, &src);
    atomic_inc(&counts[(size_t)src.row * (patchCount + 2u) + column]);
}

/* power[(column * 3 + c) * 2 ..] += the ray's power in channel c, in 64-bit fixed point; the
 * source's row names its Shooter. */
__kernel void shoot_power(__global const BvhNode* nodes, __global const LeafBlock* blocks,
                          __global const FaceInfo* faces, __global const SampleTriangle* triangles,
                          __global const uint* cdf, __global const RaySource* sources, uint sourceCount,
                          uint rayCount, uint patchCount, __global const Shooter* shooters,
                          __global uint* power) {
    const uint ray = get_global_id(0);
    if (ray >= rayCount) return;
    RaySource src;
    const uint column = cast_ray(nodes, blocks, faces, triangles, cdf, sources, sourceCount, ray, patchCount, &src);
    __global const uint* w = shooters[src.row].weight;
    volatile __global uint* sum = power + (size_t)column * 6u;
    for (int c = 0; c < 3; ++c)
        if (w[2 * c] != 0u || w[2 * c + 1] != 0u) atomic_add64(sum + 2 * c, w[2 * c], w[2 * c + 1]);
}
