/* Direct light across an element, for adaptive refinement: how far the irradiance from the
 * strongest emitters departs from linear over the element. It is found at seven points: the
 * corners, the edges' midpoints and the centroid of the element shrunk by a twentieth about its
 * centroid (so that no point sits on an edge shared with other geometry), lifted off the
 * surface. At each point, each emitter patch s contributes E_s F(point -> s) v_s: its exitance,
 * the closed-form point-to-polygon factor (polygon_factor.h) and the fraction v_s of M
 * stratified shadow rays to it that arrive. Shading interpolates linearly between corners, so
 * what it cannot show is the midpoints' and the centroid's departure from the corners' linear
 * interpolation. The results: the largest departure over the largest of the seven values, that
 * largest, the mean of the seven, and the punctual lights' part of that mean. A shadow's edge across the element shows as a large
 * departure, a smooth fall-off or a smooth penumbra on a small element as a small one.
 * Punctual lights add their irradiance at the same points by the estimator every pass uses
 * (light_tree.h's punctual_lights_at: each light through one shadow ray, or a light cut where
 * there are many): their shadows are sharp, and the refinement follows them.
 * Deterministic and free of the solver's noise. */
#pragma OPENCL FP_CONTRACT OFF

#include "kernel_args.h"
#include "rng.h"
#include "sampling.h"
#include "vector_math.h"
#include "bvh_traverse.h"
#include "polygon_factor.h"
#include "punctual_light.h"
#include "light_tree.h"

#define POINTS 7

/* elements: per element its three corners, lifted, and its unit normal. A launch takes the
 * elements first, first + 1, ... (launches are split to return promptly). */
__kernel void direct_variation(RAD_KERNEL_PARAMS(RAD_DIRECT_VARIATION_KERNEL)) {
    RAD_ELEMENT_OF_WORK_ITEM(e);
    const SceneData scene = RAD_SCENE_DATA;
    const float lift = scene.about.lift;
    __global const LiftedElement* element = &elements[e];
    const float3 a = vload3(0, element->corners[0]), b = vload3(0, element->corners[1]),
                 c = vload3(0, element->corners[2]), n = vload3(0, element->normal);
    const float3 centre = (a + b + c) / 3.0f;
    const float3 sa = centre + 0.95f * (a - centre), sb = centre + 0.95f * (b - centre), sc = centre + 0.95f * (c - centre);
    /* corners, midpoints of (a, b), (b, c), (c, a), centroid */
    const float3 points[POINTS] = {sa, sb, sc, 0.5f * (sa + sb), 0.5f * (sb + sc), 0.5f * (sc + sa), centre};
    float irradiance[POINTS] = {0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f};
    for (uint s = 0u; s < shooterCount; ++s) {
        __global const SampleTriangle* shooter = &triangles[shooters[s]];
        const float3 v0 = vload3(0, shooter->v0), e1 = vload3(0, shooter->e1), e2 = vload3(0, shooter->e2);
        const float3 sn = vload3(0, shooter->normal);
        for (uint k = 0u; k < POINTS; ++k) {
            const float3 p = points[k];
            const float f = point_to_triangle_factor(p, n, v0, v0 + e1, v0 + e2, sn);
            if (!(f > 0.0f)) continue;
            uint open = 0u;
            for (uint r = 0u; r < rays; ++r) {
                const uint4 x = scrambled_sobol4(r, rad_hash2(seed, shooters[s]));
                const float2 w = triangle_barycentrics((float2)(unit_float(x.x), unit_float(x.y)));
                const float3 q = v0 + w.x * e1 + w.y * e2 + shooter->v0[3] * sn;
                const float3 d = q - p;
                const float distance = sqrt(dot3(d, d));
                if (distance > 0.0f && trace_within(&scene.geometry, p, d / distance, distance).face < 0) ++open;
            }
            irradiance[k] += exitance[s] * f * (float)open / (float)rays;
        }
    }
    /* Punctual lights (luminance): the emitting patches' part is scaled first by sourceScale, the
     * share of the patches' power those sampled stand for (with no lights, the host scales). */
    float fromLights = 0.0f;
    if (scene.about.punctualCount > 0u) {
        for (uint k = 0u; k < POINTS; ++k) {
            uint traced = 0u;
            const float lit =
                luminance3(punctual_lights_at(&scene, points[k], n, diffuse_receiver(), lift, &traced));
            irradiance[k] = sourceScale * irradiance[k] + lit;
            fromLights += lit;
        }
    }
    float hi = 0.0f, sum = 0.0f;
    for (uint k = 0u; k < POINTS; ++k) {
        hi = fmax(hi, irradiance[k]);
        sum += irradiance[k];
    }
    const float ea = irradiance[0], eb = irradiance[1], ec = irradiance[2];
    float departure = fabs(irradiance[3] - 0.5f * (ea + eb));
    departure = fmax(departure, fabs(irradiance[4] - 0.5f * (eb + ec)));
    departure = fmax(departure, fabs(irradiance[5] - 0.5f * (ec + ea)));
    departure = fmax(departure, fabs(irradiance[6] - (ea + eb + ec) / 3.0f));
    out[e] = (float4)(hi > 0.0f ? departure / hi : 0.0f, hi, sum / (float)POINTS, fromLights / (float)POINTS);
}
