/* The reference path tracer: images of a scene that do not depend on its meshing, to measure
 * the radiosity solution's images against. Mirrors, rough metals and glass (material.h) reflect
 * and refract the path, its weight times what they pass on (a choice between glass's reflection
 * and transmission drawn by its Fresnel reflectance; a rough metal's direction drawn from its
 * GGX lobe's visible normals, ggx.h). At a rough metal every punctual light, an emitting surface
 * and an environment map are sampled as at a diffuse surface, weighed against the lobe's own
 * direction by the balance heuristic (light_estimate.h). A diffuse surface under glTF's specular
 * layer (material.h: layered_lobe) samples them so too, and its path goes on by the layer's lobe
 * or the diffuse part's cosine, one drawn by its share of the albedo. Every other surface is diffuse, as the
 * radiosity model is: at every hit the radiance is L = Le + rho * L(next), with the next direction cosine-distributed about
 * the side that was hit, so the cosine and 1/pi of the diffuse BRDF cancel against the pdf and
 * the path's weight is simply the product of the reflectances. Emitting surfaces are also
 * sampled at every hit that may reflect once more: one point on an emitting patch drawn by
 * power and its shadow ray (surface_lights.h), combined with the paths that hit the patch by
 * the balance heuristic (without it, with surfaceLightCount 0, only paths that hit an emitter
 * find its light). A uniform sky's light is found only by paths that leave the scene. An environment
 * map, whose sun a cosine-distributed path would rarely find, is also sampled at every hit that
 * may reflect once more: one direction drawn from the map (environment.h) and its shadow ray,
 * combined with the paths that leave the scene by multiple importance sampling (the balance
 * heuristic over the cosine and map densities), so neither is counted twice. Punctual lights, which
 * no path can hit, are sampled at every hit that may reflect once more: one shadow ray to each
 * (a light cut with many, light_tree.h; through thin panes, shadow_ray.h), adding
 * weight * rho * E / pi, E their irradiance there. Textured faces read rho and Le from their textures at the hit (texture.h);
 * a normal map (material.h: mapped_normal) turns the normal a surface reflects about. No
 * clamping, so every path is an unbiased estimate of the pixel's radiance (with many lights, up
 * to the cut's bounded error).
 *
 * Single-sided faces are black on the back (the path ends there); a double-sided face emits
 * and reflects on both sides. After RAD_ROULETTE_AFTER reflections a path goes on with
 * probability q = the surface's largest reflectance (at most RAD_MAX_SURVIVAL), its weight
 * divided by q: unbiased, and paths in a bright closed room still end.
 *
 * Randomness is counter-based: sample s of pixel p at depth d is a point of an Owen-scrambled
 * Sobol sequence keyed by (seed, p, d) (rng.h, path_sample), so the image depends on the
 * seed and the sample count only, never on threads or work-group sizes; across devices only
 * through float rounding (a few paths end differently). */
#pragma OPENCL FP_CONTRACT OFF

#include "kernel_args.h"
#include "rng.h"
#include "sampling.h"
#include "vector_math.h"
#include "bvh_traverse.h"
#include "camera.h"
#include "light_estimate.h"
#include "material.h"
#include "pixel_sum.h"
#include "specular_walk.h"

#define RAD_ROULETTE_AFTER 3u
#define RAD_MAX_SURVIVAL 0.95f
/* A path longer than this is cut (with RAD_MAX_SURVIVAL, the chance of getting here is below
 * 0.95^4000, about 1e-89): a guard against endless loops, not a limit that ever matters. */
#define RAD_PATH_GUARD 4096u
#define RAD_CAMERA_DEPTH 0xFFFFFFFFu
/* The depths of the environment map's and the emitting surfaces' samples: their own keys
 * (path_sample), below the camera's. */
#define RAD_MAP_DEPTH 0x40000000u
#define RAD_SURFACE_LIGHT_DEPTH 0x20000000u
#define RAD_SPECULAR_DEPTH 0x10000000u


/* A path's weight times what the surface at bounce `depth` passes on (`carried`): after
 * RAD_ROULETTE_AFTER bounces it goes on with probability q, the largest of `carried` (at most
 * RAD_MAX_SURVIVAL), decided by u, and its weight is divided by q. False: the path ends (by
 * roulette, or with nothing left to carry). */
inline bool survives(float3* weight, float3 carried, float u, uint depth) {
    if (depth >= RAD_ROULETTE_AFTER) {
        const float q = fmin(fmax(fmax(carried.x, carried.y), carried.z), RAD_MAX_SURVIVAL);
        if (!(u < q)) return false;
        *weight *= carried / q;
    } else {
        *weight *= carried;
    }
    return fmax(fmax(weight->x, weight->y), weight->z) > 0.0f;
}

/* sums[pixel]: radiance summed over samples firstSample .. firstSample + sampleCount - 1, and in
 * w the sum of the squares of the samples' luminances (for the pixel's variance); written, not
 * added: the host accumulates launches in double. rays[pixel]: rays traced.
 * maxBounces: 0 for no limit, else the most reflections a path may take (1: direct light).
 * lightSampling 0: emitting surfaces are found only by the paths that hit them. */
__kernel void pathtrace(RAD_KERNEL_PARAMS(RAD_PATHTRACE_KERNEL)) {
    const uint pixel = get_global_id(0);
    if (pixel >= width * height) return;
    const SceneData scene = RAD_SCENE_DATA;
    const SceneLights lights = scene_lights(&scene, lightSampling != 0u);
    const float lift = info->lift;
    const uint x = pixel % width, y = pixel / width;
    const uint bounceLimit = maxBounces == 0u ? RAD_PATH_GUARD : min(maxBounces, RAD_PATH_GUARD);
    PixelSum sum = pixel_sum_start();
    for (uint s = 0u; s < sampleCount; ++s) {
        const uint index = firstSample + s;
        float3 origin;
        float3 dir = pixel_ray(&camera, x, y, width, height, path_sample(seed, pixel, RAD_CAMERA_DEPTH, index).xy, &origin);
        float3 weight = (float3)(1.0f);
        float3 radiance = (float3)(0.0f);
        /* The density the last bounce drew `dir` with (a diffuse surface's cosine, a rough
         * metal's lobe); < 0 from the camera, a mirror or glass (no light sample to weigh against). */
        float cosinePdf = -1.0f;
        /* whether the path sampled the lights before (view_path.h says why it matters) */
        bool sampledBefore = false;
        for (uint depth = 0u;; ++depth) {
            const Hit hit = trace_closest(&scene.geometry, origin, dir);
            ++sum.traced;
            if (hit.face < 0) {
                radiance += weight * environment_seen(&lights.env, dir, cosinePdf);
                break;
            }
            __global const FaceInfo* face = &faces[hit.face];
            float3 n = vload3(0, face->normal);
            const bool front = dot3(dir, n) < 0.0f;
            const uint kind = material_kind(&scene, hit.face);
            const uint first = front ? face->frontPatch : face->backPatch;
            /* the back: black where it has no patches, unless light passes through (glass) */
            if (material_black_side(kind, first != RAD_NO_PATCH)) break;
            if (!front) n = -n;
            float3 le, rho;
            material_at(&scene, hit, &rho, &le);
            /* the back of single-sided glass emits nothing: it emits (if at all) from its front */
            if (first != RAD_NO_PATCH)
                radiance += weight * emission_seen(&scene, &lights.surface, hit, first, le, cosinePdf, -dot3(dir, n));
            if (depth >= bounceLimit) break;
            const float3 p = origin + hit.t * dir;
            const float off = ray_offset(origin, p, lift);
            if (!material_is_diffuse(kind)) {
                /* Reflected or refracted: no light sample can find a mirror's or smooth glass's
                 * path; a rough metal samples every kind of light for its lobe, rough glass for
                 * what its microfacets reflect (material.h: specular_lobe). */
                Lobe lobe;
                const bool sampled = material_samples_lights(&scene, hit.face, kind, front);
                if (sampled) {
                    lobe = specular_lobe(&scene, hit, dir, vload3(0, face->normal));
                    lobe.behind = p - off * n;
                    if (sampledBefore && lobe.behindLights != RAD_BEHIND_NONE) lobe.behindLights = RAD_BEHIND_SURFACES;
                    sampledBefore = true;
                    radiance += weight * direct_light(&scene, &lights, &lobe, p + off * n, lift, seed, pixel,
                                                      depth | RAD_SURFACE_LIGHT_DEPTH, depth | RAD_MAP_DEPTH, index,
                                                      &sum.traced);
                }
                const uint4 u = path_sample(seed, pixel, depth | RAD_SPECULAR_DEPTH, index);
                float3 carried;
                bool through;
                const float3 drawn = (float3)(unit_float(u.x), unit_float(u.z), unit_float(u.w));
                dir = specular_step(&scene, hit, dir, drawn, lift, false, &origin, &carried, &through);
                if (!survives(&weight, carried, unit_float(u.y), depth)) break;
                cosinePdf = sampled ? lobe_density(&lobe, dir) : -1.0f;
                continue;
            }
#ifdef RAD_LAYERS
            if (material_layered(&scene, hit.face)) { /* the diffuse part or the layer goes on */
                const Lobe lobe = layered_lobe(&scene, hit, dir, vload3(0, face->normal), rho);
                sampledBefore = true;
                radiance += weight * direct_light(&scene, &lights, &lobe, p + off * n, lift, seed, pixel,
                                                  depth | RAD_SURFACE_LIGHT_DEPTH, depth | RAD_MAP_DEPTH, index,
                                                  &sum.traced);
                const uint4 u = path_sample(seed, pixel, depth, index);
                float3 carried;
                bool glossy;
                const float3 next = layered_scatter(&lobe, unit_float(u.w), (float2)(unit_float(u.x), unit_float(u.y)),
                                                    &carried, &cosinePdf, &glossy);
                if (!survives(&weight, carried, unit_float(u.z), depth)) break;
                origin = p + off * n;
                dir = next;
                continue;
            }
#endif
            const Lobe lobe = surface_diffuse_lobe(&scene, hit, rho, n, front, true);
            sampledBefore = true;
            radiance += weight * direct_light(&scene, &lights, &lobe, p + off * n, lift, seed, pixel,
                                              depth | RAD_SURFACE_LIGHT_DEPTH, depth | RAD_MAP_DEPTH, index, &sum.traced);
            const uint4 u = path_sample(seed, pixel, depth, index);
            if (!survives(&weight, rho, unit_float(u.z), depth)) break;
            origin = p + off * n;
            dir = diffuse_scatter(&lobe, (float2)(unit_float(u.x), unit_float(u.y)), &cosinePdf);
#ifdef RAD_NORMAL_MAPS
            if (!(dot3(dir, n) > 0.0f)) break; /* a normal map's cosine drew it into the face */
#endif
        }
        pixel_sum_add(&sum, radiance);
    }
    pixel_sum_write(&sum, sums, rays, pixel);
}
