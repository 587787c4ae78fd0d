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
 *         rho H / pi there (H interpolated over the element it lands on, emission excluded),
 *         times pi, the cosine's density cancelling the cosine.
 *   - E_caustic, with mirrors or glass (caustics != 0, below): the solution's light that
 *     reached this point by way of them, interpolated as vertexCaustic.
 * The solution's H includes the direct light at the place the gather ray lands: that is light
 * that has bounced once by the time it reaches the camera's point. Emission is never read from
 * the solution, and light by way of mirrors or glass is either read as E_caustic or found by
 * cosine rays, never both, so no light is counted twice. Punctual lights' light straight
 * through thin panes is direct light (their shadow rays cross panes: shadow_ray.h); what they
 * send off mirrors or through glass otherwise is in E_caustic (rays drawn from the lights,
 * host/light/punctual_caustics.h), since no ray can hit them.
 *
 * Randomness as the path tracer's: sample s of pixel p is a point of Owen-scrambled Sobol
 * sequences keyed by (seed, p, what it is for) (rng.h, path_sample), so the image depends on
 * the seed and the sample count only, never on threads or work-group sizes. */
#pragma OPENCL FP_CONTRACT OFF

#include "scene_data.h"
#include "rng.h"
#include "sampling.h"
#include "vector_math.h"
#include "bvh_traverse.h"
#include "camera.h"
#include "light_tree.h"
#include "environment.h"
#include "face_material.h"
#include "solution_lookup.h"
#include "surface_lights.h"
#include "specular.h"
#include "glossy_lights.h"

#define RAD_VIEW_DIRECT 1u
#define RAD_VIEW_FINAL_GATHER 2u

/* The keys of a pixel's sample sequences (path_sample), one per use. */
#define RAD_KEY_CAMERA 0xFFFFFFFFu
#define RAD_KEY_SURFACE_LIGHT 1u /* each bounce's keys: these, or'd with the bounce << 8 */
#define RAD_KEY_MAP 2u
#define RAD_KEY_COSINE 3u
#define RAD_KEY_SPECULAR 4u /* these three or'd with the diffuse bounce << 8 and the specular bounce << 3 */
#define RAD_KEY_GLOSSY_LIGHT 5u
#define RAD_KEY_GLOSSY_MAP 6u

#define RAD_ELEMENT_STRIDE 6u /* float4s per element (host/light/direct_light_kernels.h) */


/* What the solution reflects toward a ray that hit `hit` travelling along dir: rho H / pi, with
 * H interpolated from vertexIrradiance over the element; black on a single-sided face's back. */
inline float3 solution_reflected(const SceneData* scene, const FaceMaterials* materials,
                                 __global const ElementNode* elements, __global const uint4* corners,
                                 __global const float4* vertexIrradiance, Hit hit, float3 dir) {
    __global const FaceInfo* face = &scene->faces[hit.face];
    const bool front = dot3(dir, vload3(0, face->normal)) < 0.0f;
    const uint first = front ? face->frontPatch : face->backPatch;
    if (first == RAD_NO_PATCH) return (float3)(0.0f);
    float3 rho, le;
    material_at(materials, hit, &rho, &le);
    const ElementPoint at = element_point(scene, elements, corners, hit, first, front);
    return rho * interpolate_vertices(vertexIrradiance, at) * (1.0f / RAD_PI);
}

/* The direct light arriving at q (unit normal n, q already off the surface): punctual lights,
 * one light sample of the emitting surfaces and, with a map, one of the environment, each
 * weighed against cosine rays where those can find the same light. Irradiance, W/m^2. */
inline float3 direct_light(const SceneData* scene, __global const PunctualLight* lights, uint lightCount,
                           uint directional, __global const LightNode* tree, const SurfaceLights* surface,
                           const Environment* env, float3 q, float3 n, float lift, uint seed, uint pixel, uint key,
                           uint index, uint* traced) {
    float3 e = (float3)(0.0f);
    if (lightCount > 0u)
        e += punctual_lights_at(scene, lights, lightCount, directional, tree, q, n, diffuse_receiver(), lift, traced);
    e += surface_light_irradiance(scene, surface, q, n, path_sample(seed, pixel, key | RAD_KEY_SURFACE_LIGHT, index),
                                  true, traced);
    if (env->info.width != 0u) {
        const uint4 m = path_sample(seed, pixel, key | RAD_KEY_MAP, index);
        float mapPdf;
        const float3 toward = environment_sample(env, m.xy, &mapPdf);
        const float cosine = dot3(toward, n);
        if (cosine > 0.0f && mapPdf > 0.0f) {
            ++*traced;
            if (trace_closest(scene, q, toward).face < 0)
                e += environment_radiance(env, toward) * (cosine / (cosine * (1.0f / RAD_PI) + mapPdf));
        }
    }
    return e;
}

/* sums[pixel]: radiance summed over samples firstSample .. firstSample + sampleCount - 1, and in
 * w the sum of the squares of the samples' luminances; written, not added (the host
 * accumulates launches in double). rays[pixel]: rays traced. mode: RAD_VIEW_DIRECT (reads
 * vertexIndirect) or RAD_VIEW_FINAL_GATHER. lift: the least distance, in metres, by which a new
 * ray's origin leaves the surface.
 *
 * Each sample is a short path. Mirrors, rough metals and glass (specular.h) pass it on, reflected
 * or refracted, up to RAD_SPECULAR_BOUNCES times between diffuse surfaces; at a rough metal the
 * lights are sampled as at a diffuse surface, weighed against the lobe's own direction
 * (glossy_lights.h), which then weighs what it finds likewise. At the first diffuse
 * surface the path shades: direct light and one cosine ray. Where the cosine ray (through any
 * mirrors) lands on a diffuse surface, direct mode stops (its indirect light came from the
 * elements), and final gather reads the solution's reflected light there.
 *
 * Light that reaches a shaded surface by way of mirrors or glass (a caustic) is counted once,
 * one of two ways. caustics != 0 (the solve carried light through them and kept apart what each
 * element received so: Solution::causticIrradiance): the shaded surface adds that light,
 * interpolated as vertexCaustic, and a cosine ray that meets a mirror or glass brings nothing
 * from the emitters, the sky or the solution (the caustic holds it all: the shots' light, and the
 * sky's and environment's that the solve's direct light found through them). caustics == 0: the
 * cosine ray follows them and emission found after them counts in full (no light sample could
 * have found that path), which at a few samples per pixel shows as sparkles.
 *
 * Final gather near a surface: where a gather ray lands closer than `near` (a few patches), the
 * solution there is too coarse to read: it averages over elements as large as the distance, and
 * misses the light's change across a contact or a corner. There the pass shades once more
 * (direct light and a cosine ray from the landing point, as at the camera's hit), up to
 * RAD_GATHER_BOUNCES times, and reads the solution only where a ray lands far enough. */
#define RAD_GATHER_BOUNCES 2u
__kernel void view_pass(RAD_SCENE_PARAMS __global const ElementNode* elements, __global const uint4* corners,
                        __global const float4* vertexIrradiance, __global const float4* vertexIndirect,
                        __global const float4* vertexCaustic, uint caustics,
                        __global const float4* reflectance, __global const float4* emission,
                        __global const FaceTexture* faceTextures, __global const float* srgb, uint textured,
                        __global const PunctualLight* lights, uint lightCount, uint directional,
                        __global const LightNode* tree, __global const SurfaceLight* surfaceLights,
                        __global const uint* surfaceEnds, __global const uint* lightOfPatch, uint surfaceLightCount,
                        EnvironmentInfo envInfo, __global const float4* envTexels, __global const uint* envRows,
                        __global const uint* envColumns, CameraRays camera, uint width, uint height,
                        uint firstSample, uint sampleCount, uint mode, uint seed, float lift, float near,
                        __global float4* sums, __global uint* rays) {
    const uint pixel = get_global_id(0);
    if (pixel >= width * height) return;
    const SceneData scene = RAD_SCENE_DATA;
    const Environment env = {envInfo, envTexels, envRows, envColumns};
    const FaceMaterials materials = {reflectance, emission, faceTextures, texels, textureSlots, srgb, textured};
    const SurfaceLights surface = {surfaceLights, surfaceEnds, lightOfPatch, surfaceLightCount};
    const bool mapped = envInfo.width != 0u;
    const uint x = pixel % width, y = pixel / width;
    float3 total = (float3)(0.0f);
    float squares = 0.0f;
    uint traced = 0u;
    for (uint s = 0u; s < sampleCount; ++s) {
        const uint index = firstSample + s;
        float3 origin;
        float3 dir = pixel_ray(&camera, x, y, width, height, path_sample(seed, pixel, RAD_KEY_CAMERA, index).xy, &origin);
        float3 radiance = (float3)(0.0f);
        float3 weight = (float3)(1.0f);
        /* the density the last diffuse bounce or rough metal drew dir with; < 0: none (MIS off) */
        float cosinePdf = -1.0f;
        uint diffuse = 0u;       /* diffuse surfaces shaded so far */
        uint specularBounces = 0u;
        float travelled = 0.0f; /* since the last diffuse surface */
        for (;;) {
            const Hit hit = trace_closest(&scene, origin, dir);
            ++traced;
            if (hit.face < 0) {
                /* past mirrors or glass from a shaded point, the caustic holds the sky's light too */
                if (caustics != 0u && diffuse > 0u && specularBounces > 0u) break;
                const float3 outside = environment_radiance(&env, dir);
                radiance += weight * (cosinePdf < 0.0f || !mapped
                                          ? outside
                                          : outside * (cosinePdf / (cosinePdf + environment_pdf(&env, dir))));
                break;
            }
            travelled += hit.t;
            __global const FaceInfo* face = &faces[hit.face];
            float3 n = vload3(0, face->normal);
            const bool front = dot3(dir, n) < 0.0f;
            const uint kind = specular_kind(&scene, hit.face);
            const uint first = front ? face->frontPatch : face->backPatch;
            if (first == RAD_NO_PATCH && kind < RAD_SPECULAR_GLASS) break; /* a black back */
            if (!front) n = -n;
            float3 rho, le;
            material_at(&materials, hit, &rho, &le);
            /* a cosine ray that passed mirrors or glass: the solution's caustic holds what it finds */
            const bool inCaustic = caustics != 0u && diffuse > 0u && specularBounces > 0u;
            if (first == RAD_NO_PATCH || inCaustic) {
                /* the back of single-sided glass emits nothing (it emits, if at all, from its
                 * front); after mirrors or glass, the caustic holds the emission found */
            } else if (cosinePdf < 0.0f) {
                radiance += weight * le;
            } else if (fmax(fmax(le.x, le.y), le.z) > 0.0f) { /* weighed against the light sample */
                const uint patch = first + grid_cell_index(face->subdivision, hit.b1, hit.b2);
                radiance += weight * le * surface_light_hit_weight(&scene, &surface, patch, cosinePdf, hit.t, -dot3(dir, n));
            }
            if (inCaustic) break; /* nothing more for this ray to find */
            const float3 p = origin + hit.t * dir;
            /* Off the surface by more than the hit point's rounding (as the path tracer). */
            const float off = fmax(lift, fmax(max_abs3(origin), max_abs3(p)) * 0x1p-18f);
            if (kind != RAD_SPECULAR_NONE) {
                if (specularBounces >= RAD_SPECULAR_BOUNCES) break;
                const uint bounceKey = (diffuse << 8) | (specularBounces << 3);
                /* A rough metal: light sampling, as at a diffuse surface; not on a cosine ray from a
                 * shaded point when the solution's caustic holds what reaches that point by way of
                 * the metal (and the ray then ends where it lands: inCaustic). */
                GlossyLobe lobe;
                const bool glossy = kind == RAD_SPECULAR_GLOSSY && !(caustics != 0u && diffuse > 0u);
                if (glossy) {
                    lobe = glossy_lobe(&scene.specular[hit.face], hit, dir, vload3(0, face->normal));
                    const uint lightKey = bounceKey | RAD_KEY_GLOSSY_LIGHT, mapKey = bounceKey | RAD_KEY_GLOSSY_MAP;
                    radiance += weight * glossy_direct_light(&scene, lights, lightCount, directional, tree,
                                                             &surface, &env, &lobe, p + off * n, lift, seed, pixel,
                                                             lightKey, mapKey, index, &traced);
                }
                const uint4 u = path_sample(seed, pixel, bounceKey | RAD_KEY_SPECULAR, index);
                float3 carried;
                bool through;
                dir = specular_scatter(&scene.specular[hit.face], hit, dir, vload3(0, face->normal),
                                       (float2)(unit_float(u.x), unit_float(u.y)), &carried, &through);
                weight *= carried;
                if (!(fmax(fmax(weight.x, weight.y), weight.z) > 0.0f)) break;
                origin = p + (through ? -off : off) * n;
                cosinePdf = glossy ? glossy_density(&lobe, dir) : -1.0f; /* weighs what dir finds */
                ++specularBounces;
                continue;
            }
            if (diffuse > 0u) { /* a gather ray's landing point */
                if (mode == RAD_VIEW_DIRECT || inCaustic) break;
                if (!(travelled < near) || diffuse > RAD_GATHER_BOUNCES) {
                    radiance += weight * solution_reflected(&scene, &materials, elements, corners, vertexIrradiance,
                                                            hit, dir);
                    break;
                }
            }
            const float3 q = p + off * n;
            const uint key = diffuse << 8;
            float3 e = direct_light(&scene, lights, lightCount, directional, tree, &surface, &env, q, n, lift, seed, pixel,
                                    key, index, &traced);
            if (mode == RAD_VIEW_DIRECT || caustics != 0u) {
                const ElementPoint at = element_point(&scene, elements, corners, hit, first, front);
                if (mode == RAD_VIEW_DIRECT) e += interpolate_vertices(vertexIndirect, at);
                if (caustics != 0u) e += interpolate_vertices(vertexCaustic, at);
            }
            radiance += weight * rho * e * (1.0f / RAD_PI);
            /* The cosine ray: the cosine's density cancels the cosine and 1 / pi of the BRDF. */
            const uint4 u = path_sample(seed, pixel, key | RAD_KEY_COSINE, index);
            float3 t, b;
            frame_about(n, &t, &b);
            const float3 w = cosine_hemisphere((float2)(unit_float(u.x), unit_float(u.y)));
            dir = w.x * t + w.y * b + w.z * n;
            cosinePdf = w.z * (1.0f / RAD_PI);
            origin = q;
            weight *= rho;
            if (!(fmax(fmax(weight.x, weight.y), weight.z) > 0.0f)) break;
            ++diffuse;
            specularBounces = 0u;
            travelled = 0.0f;
        }
        total += radiance;
        const float lum = (0.2126f * radiance.x + 0.7152f * radiance.y) + 0.0722f * radiance.z;
        squares += lum * lum;
    }
    sums[pixel] = (float4)(total, squares);
    rays[pixel] = traced;
}

/* The solution's indirect irradiance over each element, for the direct mode: the mean, over
 * `rays` cosine-distributed rays from stratified points of the element, of pi times the
 * solution's reflected radiance where each lands (solution_reflected); rays that leave the
 * scene or find only emission bring nothing (that light is direct); with caustics, so do rays
 * that meet a mirror or glass (the element's caustic light holds it). seed: already keyed by the
 * host to this use (util/sample_streams.h). out[e]: W/m^2, rgb. The
 * elements are laid out as for direct_light.cl (host/light/direct_light_kernels.h); a launch
 * takes elements first, first + 1, ... and every result depends only on its element. */
__kernel void element_indirect(RAD_SCENE_PARAMS __global const float4* layout, uint first, uint elementCount,
                               __global const ElementNode* elements, __global const uint4* corners,
                               __global const float4* vertexIrradiance, __global const float4* reflectance,
                               __global const float4* emission, __global const FaceTexture* faceTextures,
                               __global const float* srgb, uint textured, uint caustics, uint rays, uint seed, __global float4* out) {
    const uint e = first + get_global_id(0);
    if (e >= elementCount) return;
    const SceneData scene = RAD_SCENE_DATA;
    const FaceMaterials materials = {reflectance, emission, faceTextures, texels, textureSlots, srgb, textured};
    __global const float4* element = layout + (size_t)e * RAD_ELEMENT_STRIDE;
    const float3 a = element[0].xyz, b = element[1].xyz, c = element[2].xyz, n = element[3].xyz;
    const float lift = element[3].w;
    float3 t, bt;
    frame_about(n, &t, &bt);
    const uint key = rad_hash2(seed, e);
    float3 sum = (float3)(0.0f);
    for (uint r = 0u; r < rays; ++r) {
        const uint4 u = scrambled_sobol4(r, key);
        const float2 w = triangle_barycentrics((float2)(unit_float(u.x), unit_float(u.y)));
        float3 origin = a + w.x * (b - a) + w.y * (c - a) + lift * n;
        const float3 d = cosine_hemisphere((float2)(unit_float(u.z), unit_float(u.w)));
        float3 dir = d.x * t + d.y * bt + d.z * n;
        float3 carried = (float3)(1.0f);
        Hit hit = trace_closest(&scene, origin, dir);
        /* Through mirrors and glass to the diffuse surface the ray shows. */
        for (uint k = 0u; hit.face >= 0 && k <= RAD_SPECULAR_BOUNCES; ++k) {
            const uint kind = specular_kind(&scene, hit.face);
            if (kind == RAD_SPECULAR_NONE) break;
            __global const FaceInfo* face = &faces[hit.face];
            float3 fn = vload3(0, face->normal);
            const bool front = dot3(dir, fn) < 0.0f;
            if (k == RAD_SPECULAR_BOUNCES || caustics != 0u ||
                ((front ? face->frontPatch : face->backPatch) == RAD_NO_PATCH && kind < RAD_SPECULAR_GLASS)) {
                hit.face = -1; /* absorbed there, or in the element's caustic light: brings nothing */
                break;
            }
            if (!front) fn = -fn;
            const float3 p = origin + hit.t * dir;
            const float off = fmax(lift, fmax(max_abs3(origin), max_abs3(p)) * 0x1p-18f);
            float3 f;
            bool through;
            const uint4 u = path_sample(seed, e, RAD_KEY_SPECULAR | ((k + 1u) << 3), r);
            dir = specular_scatter(&scene.specular[hit.face], hit, dir, vload3(0, face->normal),
                                   (float2)(unit_float(u.x), unit_float(u.y)), &f, &through);
            carried *= f;
            origin = p + (through ? -off : off) * fn;
            hit = trace_closest(&scene, origin, dir);
        }
        if (hit.face >= 0)
            sum += carried * solution_reflected(&scene, &materials, elements, corners, vertexIrradiance, hit, dir);
    }
    out[e] = (float4)(RAD_PI * sum / (float)max(rays, 1u), 0.0f);
}
