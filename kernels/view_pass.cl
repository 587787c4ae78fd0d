/* The camera pass's direct and final-gather modes (host/render/view_pass.h): the second pass of
 * the two-pass method, which computes per pixel what the mesh cannot show and reads from the
 * radiosity solution only the light that has bounced at least once.
 *
 * At the first surface a camera ray hits, the radiance is Le + rho / pi (E_direct + E_indirect):
 *   - E_direct, the light that arrives straight from the emitters, by sampling them: a point on
 *     an emitting patch and its shadow ray (surface_lights.h), every punctual light's shadow ray
 *     (light_tree.h), a direction from an environment map (environment.h); and one ray drawn by
 *     the cosine, which finds the emitters' light where it hits them or leaves the scene,
 *     weighed against the light samples by the balance heuristic.
 *   - E_indirect, the light every other surface reflects there:
 *       direct mode: the solution's indirect irradiance interpolated over the elements
 *         (element_indirect below made it, per element, and the host per vertex);
 *       final-gather mode: where that same cosine ray lands, the solution's reflected radiance
 *         rho H / pi there (H the mean over the element it lands on, emission excluded;
 *         view_path.h's solution_reflected says why not interpolated),
 *         times pi, the cosine's density cancelling the cosine.
 *   - E_caustic, with mirrors or glass (caustics != 0, below): the solution's light that
 *     reached this point by way of them, interpolated as vertexCaustic.
 * The solution's H includes the direct light at the place the gather ray lands: that is light
 * that has bounced once by the time it reaches the camera's point. Emission is never read from
 * the solution, and light by way of mirrors or glass is either read as E_caustic or found by
 * cosine rays, never both, so no light is counted twice. Punctual lights' light straight
 * through thin panes is direct light (their shadow rays cross panes: shadow_ray.h); what they
 * send off mirrors or through glass otherwise is in E_caustic (rays drawn from the lights,
 * host/solver/punctual_caustics.h), since no ray can hit them.
 *
 * Randomness as the path tracer's: sample s of pixel p is a point of Owen-scrambled Sobol
 * sequences keyed by (seed, p, what it is for) (rng.h, path_sample), so the image depends on
 * the seed and the sample count only, never on threads or work-group sizes. */
#pragma OPENCL FP_CONTRACT OFF

#include "kernel_args.h"
#include "view_path.h"
#include "camera.h"
#include "element_shape.h"
#include "pixel_sum.h"

/* sums[pixel]: radiance summed over samples firstSample .. firstSample + sampleCount - 1, and in
 * w the sum of the squares of the samples' luminances; written, not added (the host
 * accumulates launches in double). rays[pixel]: rays traced. mode: RAD_VIEW_DIRECT (reads
 * vertexIndirect) or RAD_VIEW_FINAL_GATHER. lift: the least distance, in metres, by which a new
 * ray's origin leaves the surface.
 *
 * Each sample is the path view_path.h follows from the camera. */
__kernel void view_pass(RAD_KERNEL_PARAMS(RAD_VIEW_PASS_KERNEL)) {
    const uint pixel = get_global_id(0);
    if (pixel >= width * height) return;
    const ViewPath path = RAD_VIEW_PATH(mode, seed, near);
    Hit none; /* no start: the path starts at the camera */
    none.face = -1;
    none.t = none.b1 = none.b2 = 0.0f;
    const uint x = pixel % width, y = pixel / width;
    PixelSum sum = pixel_sum_start();
    for (uint s = 0u; s < sampleCount; ++s) {
        const uint index = firstSample + s;
        float3 origin;
        const float3 dir =
            pixel_ray(&camera, x, y, width, height, path_sample(seed, pixel, RAD_KEY_CAMERA, index).xy, &origin);
        pixel_sum_add(&sum, view_path_radiance(&path, origin, dir, none, false, pixel, index, &sum.traced));
    }
    pixel_sum_write(&sum, sums, rays, pixel);
}

/* The solution's indirect irradiance over each element, for the direct mode: the mean, over
 * `rays` cosine-distributed rays from stratified points of the element, of pi times the
 * solution's reflected radiance where each lands (solution_reflected); rays that leave the
 * scene or find only emission bring nothing (that light is direct); with caustics, so do rays
 * that meet a mirror or glass (the element's caustic light holds it). seed: already keyed by the
 * host to this use (util/sample_streams.h). out[e]: W/m^2, rgb. The
 * elements are laid out as for direct_light.cl (host/device/element_records.h); a launch
 * takes elements first, first + 1, ... and every result depends only on its element. */
__kernel void element_indirect(RAD_KERNEL_PARAMS(RAD_ELEMENT_INDIRECT_KERNEL)) {
    RAD_ELEMENT_OF_WORK_ITEM(e);
    const SceneData scene = RAD_SCENE_DATA;
    const ElementShape shape = element_shape(&layout[e]);
    const float3 n = shape.normal;
    float3 t, bt;
    frame_about(n, &t, &bt);
    const uint key = rad_hash2(seed, e);
    float3 sum = (float3)(0.0f);
    for (uint r = 0u; r < rays; ++r) {
        const uint4 u = scrambled_sobol4(r, key);
        const float2 w = triangle_barycentrics((float2)(unit_float(u.x), unit_float(u.y)));
        const float3 origin = element_origin(&shape, w, n);
        const float3 d = cosine_hemisphere((float2)(unit_float(u.z), unit_float(u.w)));
        /* Through mirrors and glass to the diffuse surface the ray shows; with caustics, the
         * first one ends it (the element's caustic light holds what it would bring). */
        SpecularWalk walk = specular_walk_from(&scene, origin, d.x * t + d.y * bt + d.z * n);
#ifdef RAD_SPECULAR_TRANSPORT
        const uint end = walk_specular(&scene, &walk, caustics != 0u ? 0u : RAD_SPECULAR_BOUNCES,
                                       rad_hash2(key ^ RAD_KEY_SPECULAR, r), shape.lift, false, 0);
#else
        const uint end = walk.hit.face < 0 ? RAD_WALK_OUTSIDE : RAD_WALK_SURFACE;
#endif
        if (end == RAD_WALK_SURFACE)
            sum += walk.weight * solution_reflected(&scene, elements, elementIrradiance, walk.hit, walk.dir);
    }
    out[e] = (float4)(RAD_PI * sum / (float)max(rays, 1u), 0.0f);
}
