/* Hemicube form factors (Cohen and Greenberg 1985, the seed's method): a unit hemicube over the
 * centre of each shooter patch, the top face R x R pixels, each of the four sides R x R/2. A
 * pixel's delta form factor is dA / (pi (x^2 + y^2 + 1)^2) on the top face (pixel centre
 * (x, y, 1)) and z dA / (pi (y^2 + z^2 + 1)^2) on a side (pixel centre at height z), with
 * dA = (2 / R)^2. Each pixel sees the nearest patch along the ray through its centre (a
 * z-buffer with point sampling, as the rasterised hemicube is); its weight goes to that
 * patch's column, in 32-bit fixed point (units of 2^-32), summed with integer atomics. Pixels
 * that see nothing, or a black back, go to column patchCount. With `jitter` the cube turns
 * about the normal by an angle drawn per shooter, which breaks up aliasing. */
#pragma OPENCL FP_CONTRACT OFF

#include "kernel_args.h"
#include "rng.h"
#include "sampling.h"
#include "vector_math.h"
#include "bvh_traverse.h"
#include "patch_lookup.h"

/* Direction (in the patch's frame: x along the tangent, z along the normal) and weight of pixel
 * `pixel` of a hemicube with R pixels along the top face's edge. */
inline float4 hemicube_pixel(uint pixel, uint R) {
    const float dA = (2.0f / (float)R) * (2.0f / (float)R);
    if (pixel < R * R) {
        const float x = -1.0f + (2.0f * (float)(pixel % R) + 1.0f) / (float)R;
        const float y = -1.0f + (2.0f * (float)(pixel / R) + 1.0f) / (float)R;
        const float d = x * x + y * y + 1.0f;
        return (float4)(x, y, 1.0f, dA / (RAD_PI * d * d));
    }
    const uint sidePixel = pixel - R * R, halfR = R / 2u;
    const uint side = sidePixel / (R * halfR), within = sidePixel % (R * halfR);
    const float s = -1.0f + (2.0f * (float)(within % R) + 1.0f) / (float)R;
    const float z = (2.0f * (float)(within / R) + 1.0f) / (float)R;
    const float d = s * s + z * z + 1.0f;
    const float w = z * dA / (RAD_PI * d * d);
    switch (side) {
        case 0: return (float4)(1.0f, s, z, w);
        case 1: return (float4)(-1.0f, s, z, w);
        case 2: return (float4)(s, 1.0f, z, w);
        default: return (float4)(s, -1.0f, z, w);
    }
}

__kernel void hemicube_rows(RAD_KERNEL_PARAMS(RAD_HEMICUBE_ROWS_KERNEL)) {
    const uint perCube = resolution * resolution + 2u * resolution * resolution;
    const uint gid = get_global_id(0);
    if (gid >= shooterCount * perCube) return;
    const SceneGeometry scene = RAD_SCENE_GEOMETRY;
    const uint k = gid / perCube, pixel = gid % perCube;
    __global const SampleTriangle* tri = &triangles[shooters[k]];
    const float3 n = vload3(0, tri->normal), t = vload3(0, tri->tangent);
    float3 tangent = t, bitangent = cross3(n, t);
    if (jitterSeed != 0u) {
        /* A uniform direction in the plane, without trigonometry: a uniform disk point, normalised. */
        const uint h = rad_hash2(jitterSeed, shooters[k]);
        float2 c = concentric_disk((float2)(unit_float(h), unit_float(rad_hash(h))));
        if (c.x == 0.0f && c.y == 0.0f) c = (float2)(1.0f, 0.0f);
        c = c / sqrt(c.x * c.x + c.y * c.y);
        tangent = c.x * t + c.y * bitangent;
        bitangent = cross3(n, tangent);
    }
    const float4 p = hemicube_pixel(pixel, resolution);
    const float3 dir = normalize3(p.x * tangent + p.y * bitangent + p.z * n);
    const float3 centre = vload3(0, tri->v0) + (vload3(0, tri->e1) + vload3(0, tri->e2)) / 3.0f + tri->v0[3] * n;
    const Hit hit = trace_closest(&scene, centre, dir);
    uint column = patchCount;
    if (hit.face >= 0) {
        __global const FaceInfo* face = &faces[hit.face];
        const bool front = dot3(dir, vload3(0, face->normal)) < 0.0f;
        const uint first = front ? face->frontPatch : face->backPatch;
        if (first != RAD_NO_PATCH) column = first + grid_cell_index(face->subdivision, hit.b1, hit.b2);
    }
    atomic_add(&rows[(size_t)k * (patchCount + 1u) + column], convert_uint_sat(p.w * 4294967296.0f + 0.5f));
}
