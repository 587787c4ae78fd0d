/* Ray-shooting form factors. Each work item casts one ray of one source (shared_types.h) and
 * adds one to the count of whatever it lands on in the source's row: the patch hit, or
 * column stride - 2 when it leaves the scene, or column stride - 1 when it hits the black back
 * of a single-sided face. With rays from a patch spread uniformly over it and cosine-
 * distributed, count_j / rays estimates the form factor F_ij. Integer counts make the result
 * independent of the order in which work items run. */
#pragma OPENCL FP_CONTRACT OFF

#include "shared_types.h"
#include "rng.h"
#include "sampling.h"
#include "bvh_traverse.h"
#include "patch_lookup.h"
#include "ray_source.h"

/* The column a hit is counted in. */
inline uint hit_column(__global const FaceInfo* faces, Hit hit, float3 dir, uint stride) {
    if (hit.face < 0) return stride - 2u;
    __global const FaceInfo* face = &faces[hit.face];
    const bool front = dot(dir, vload3(0, face->normal)) < 0.0f;
    const uint first = front ? face->frontPatch : face->backPatch;
    if (first == RAD_NO_PATCH) return stride - 1u;
    return first + grid_cell_index(face->subdivision, hit.b1, hit.b2);
}

__kernel void shoot(__global const BvhNode* nodes, __global const LeafBlock* blocks, __global const FaceInfo* faces,
                    __global const SampleTriangle* triangles, __global const uint* cdf,
                    __global const RaySource* sources, uint sourceCount, uint rayCount, __global uint* counts,
                    uint stride) {
    const uint ray = get_global_id(0);
    if (ray >= rayCount) return;
    const RaySource src = sources[find_source(sources, sourceCount, ray)];
    const uint4 x = scrambled_sobol4(src.firstSample + (ray - src.firstRay), src.scramble);
    float u0;
    const uint triangle = pick_triangle(cdf, src, x.x, &u0);
    const float4 u = (float4)(u0, unit_float(x.y), unit_float(x.z), unit_float(x.w));
    const SourceRay r = source_ray(&triangles[triangle], u);
    const Hit hit = trace_closest(nodes, blocks, r.org, r.dir);
    atomic_inc(&counts[(size_t)src.row * stride + hit_column(faces, hit, r.dir, stride)]);
}
