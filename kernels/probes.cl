/* Entry points that expose device functions to the tests (tests/test_kernels.cpp), so the
 * very code the solver runs is checked against host references. Not used by the program. */
#pragma OPENCL FP_CONTRACT OFF

#include "kernel_args.h"
#include "rng.h"
#include "sampling.h"
#include "vector_math.h"
#include "bvh_traverse.h"
#include "shaft.h"
#include "patch_lookup.h"
#include "element_lookup.h"
#include "environment.h"
#include "fixed_point.h"
#include "material.h"

/* parts[i] = fixed_part(amounts[i], fractions[i]): the part of a signed 64-bit fixed-point
 * amount a mirror or glass passes on (shoot.cl's walk through them, specular_walk.h). */
__kernel void probe_fixed_part(RAD_KERNEL_PARAMS(RAD_PROBE_FIXED_PART_ARGS)) {
    const uint i = get_global_id(0);
    if (i >= count) return;
    parts[i] = fixed_part(amounts[i], fractions[i]);
}

/* The share xs[i] falls on among `shares` shares whose ends, then guide, are `table`: by the
 * whole table's search (picks) and by the guide (guided). */
__kernel void probe_pick(RAD_KERNEL_PARAMS(RAD_PROBE_PICK_ARGS)) {
    const uint i = get_global_id(0);
    if (i >= count) return;
    float rescaled;
    picks[i] = pick_share(table, shares, xs[i], &rescaled);
    guided[i] = pick_guided(table, table + shares, shares, xs[i]);
}

__kernel void probe_grid_cell(RAD_KERNEL_PARAMS(RAD_PROBE_GRID_CELL_ARGS)) {
    const uint i = get_global_id(0);
    if (i >= count) return;
    cells[i] = grid_cell_index(n, barycentrics[i].x, barycentrics[i].y);
}

/* The element of patches[i] holding the point with weights weights[i] on the patch's corners,
 * and the point's weights on the element's corners. */
__kernel void probe_locate_element(RAD_KERNEL_PARAMS(RAD_PROBE_LOCATE_ELEMENT_ARGS)) {
    const uint i = get_global_id(0);
    if (i >= count) return;
    float3 w = weights[i].xyz;
    elements[i] = locate_element(nodes, patches[i], &w);
    inElement[i] = (float4)(w, 0.0f);
}

/* Closest hit of each ray: face (or -1), t, b1, b2. */
__kernel void probe_trace(RAD_KERNEL_PARAMS(RAD_PROBE_TRACE_KERNEL)) {
    const uint i = get_global_id(0);
    if (i >= count) return;
    const SceneGeometry scene = RAD_SCENE_GEOMETRY;
    const Hit hit = trace_closest(&scene, origins[i].xyz, directions[i].xyz);
    hitFaces[i] = hit.face;
    hits[i] = (float4)(hit.t, hit.b1, hit.b2, 0.0f);
}

/* Whether any face may meet the shaft of the six points corners[6 i .. 6 i + 5] (shaft.h). */
__kernel void probe_shaft(RAD_KERNEL_PARAMS(RAD_PROBE_SHAFT_KERNEL)) {
    const uint i = get_global_id(0);
    if (i >= count) return;
    const SceneGeometry scene = RAD_SCENE_GEOMETRY;
    float3 p[RAD_SHAFT_POINTS];
    for (int k = 0; k < RAD_SHAFT_POINTS; ++k) p[k] = corners[RAD_SHAFT_POINTS * i + k].xyz;
    const Shaft shaft = make_shaft(p, margin);
    blocked[i] = shaft_may_be_blocked(&scene, &shaft) ? 1 : 0;
}

/* How many punctual lights and sampled emitting patches the scene's arrays hold, as a kernel
 * reads them. */
__kernel void probe_lights(RAD_KERNEL_PARAMS(RAD_PROBE_LIGHTS_KERNEL)) {
    if (get_global_id(0) != 0) return;
    const SceneData scene = RAD_SCENE_DATA;
    counts[0] = scene.about.punctualCount;
    counts[1] = scene.about.surfaceLightCount;
}

/* Sample i of the sequence keyed by `key`, as the shoot kernel draws it. */
__kernel void probe_samples(RAD_KERNEL_PARAMS(RAD_PROBE_SAMPLES_ARGS)) {
    const uint i = get_global_id(0);
    if (i >= count) return;
    samples[i] = scrambled_sobol4(i, key);
}

/* The sampling maps: disk point, cosine direction, triangle barycentrics, sin and cos. */
__kernel void probe_maps(RAD_KERNEL_PARAMS(RAD_PROBE_MAPS_ARGS)) {
    const uint i = get_global_id(0);
    if (i >= count) return;
    disk[i] = concentric_disk(u[i]);
    direction[i] = (float4)(cosine_hemisphere(u[i]), 0.0f);
    barycentrics[i] = triangle_barycentrics(u[i]);
    const float x = RAD_PI_4 * (2.0f * u[i].x - 1.0f);
    sinCos[i] = (float2)(sin_quarter(x), cos_quarter(x));
}

/* The environment map as the kernels see it: for directions[i], its map coordinates (u, t) and
 * sampling density in mapped[i] (x, y, z), its radiance in radiance[i]; and the direction the
 * sampler draws from draws[i], with its density (w) in drawn[i]. */
__kernel void probe_environment(RAD_KERNEL_PARAMS(RAD_PROBE_ENVIRONMENT_ARGS)) {
    const uint i = get_global_id(0);
    if (i >= count) return;
    const Environment env = {info, texels, rows, columns};
    const float3 d = directions[i].xyz;
    const float2 ut = environment_coordinates(d);
    mapped[i] = (float4)(ut, environment_pdf(&env, d), 0.0f);
    radiance[i] = (float4)(environment_radiance(&env, d), 0.0f);
    float pdf;
    const float3 e = environment_sample(&env, draws[i], &pdf);
    drawn[i] = (float4)(e, pdf);
}

/* A rough metal's lobe (ggx.h, material.h) for light arriving along dir (unit, below the surface
 * z = 0, shading normal +z; the face's own normal `face`, on the same side), F0 1, GGX alpha:
 * drawn[i] the direction glossy_scatter draws from u[i] (w: its weight), lobe[i] =
 * ggx_reflection(wo, drawn direction) (f cos_i without Fresnel) and wo . h in y; albedo[i] =
 * glossy_albedo keyed by i (single scattering: the energy scale 1). */
__kernel void probe_glossy(RAD_KERNEL_PARAMS(RAD_PROBE_GLOSSY_ARGS)) {
    const uint i = get_global_id(0);
    if (i >= count) return;
    const float3 n = (float3)(0.0f, 0.0f, 1.0f), d = dir.xyz, ng = face.xyz;
    const float cosi = -d.z;
    float3 w;
    const float3 out = glossy_scatter((float3)(1.0f), alpha, n, ng, d, cosi, u[i], &w);
    drawn[i] = (float4)(out, w.x);
    float cosine;
    const float f = ggx_reflection(-d, out, alpha, &cosine);
    lobe[i] = (float2)(f, cosine);
    albedo[i] = glossy_albedo(0, (float3)(1.0f), alpha, n, ng, d, cosi, i).x;
}
