/* The camera pass's path from a surface point onward (kernels/view_pass.cl says what it
 * computes and why; the lightmap's texels, kernels/lightmap.cl, take the same path from their
 * own points): shared so that a texel and a pixel showing the same point see the same light. */
#ifndef RADIOSITY_VIEW_PATH_H
#define RADIOSITY_VIEW_PATH_H

#include "scene_data.h"
#include "rng.h"
#include "sampling.h"
#include "vector_math.h"
#include "bvh_traverse.h"
#include "light_estimate.h"
#include "material.h"
#include "solution_lookup.h"
#include "specular_walk.h"

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
#define RAD_KEY_TEXEL 0xFFFFFFFEu /* a lightmap texel's points (kernels/lightmap.cl) */
#define RAD_KEY_TEXEL_PROBE 0xFFFFFFFDu /* its anchor's probes (kernels/lightmap.cl) */

/* What the solution reflects toward a ray that hit `hit` travelling along dir: rho H / pi, with
 * H the light arriving at the element it lands on (elementIrradiance: the element's mean, the
 * solve's own estimate) and rho the solution's reflectance at the hit, texture and all (under a
 * specular layer, its light reflected diffusely too); black on a single-sided face's back.
 *
 * The element's mean, not the vertices' values interpolated over it: those are fitted for the
 * eye (host/mesh/vertices.h), and where the light peaks within a few elements (a lamp's hot spot
 * on the ceiling beside it) the fits overshoot, so the interpolated light over the elements sums
 * to more than the solve delivered to them, and every gather that reads them comes out bright (a
 * room's floor +1.1 % by docs/results.md's comparison with Cycles). The means sum to what was
 * delivered, and a pixel's gather rays average over many elements, so their steps never show. */
inline float3 solution_reflected(const SceneData* scene, __global const ElementNode* elements,
                                 __global const float4* elementIrradiance, Hit hit, float3 dir) {
    __global const FaceInfo* face = &scene->geometry.faces[hit.face];
    const bool front = dot3(dir, vload3(0, face->normal)) < 0.0f;
    const uint first = front ? face->frontPatch : face->backPatch;
    if (first == RAD_NO_PATCH) return (float3)(0.0f);
    float3 rho, le;
    material_at(scene, hit, &rho, &le);
    float3 weights;
    const uint e = element_under(&scene->geometry, elements, hit, first, front, &weights);
    return material_solution_reflectance(scene, hit, rho) * elementIrradiance[e].xyz * (1.0f / RAD_PI);
}

/* What a path reads: the scene, its materials and lights, and the radiosity solution as light
 * arriving at its elements (and, where the camera sees it, at their vertices). mode: RAD_VIEW_DIRECT (reads vertexIndirect) or
 * RAD_VIEW_FINAL_GATHER. lift: the least distance, in metres, by which a new ray's origin leaves
 * the surface; near: see view_path_radiance. */
typedef struct {
    SceneData scene;
    SceneLights lights;
    __global const ElementNode* elements;
    __global const uint4* corners;
    __global const float4* elementIrradiance;
    __global const float4* vertexIndirect;
    __global const float4* vertexCaustic;
    uint caustics, mode, seed;
    float lift, near;
} ViewPath;

/* In the body of a kernel whose parameters are the scene's, then the solution's
 * (kernel_args.h: RAD_VIEW_SOLUTION_ARGS):
 *   const ViewPath path = RAD_VIEW_PATH(mode, seed, near); */
#define RAD_VIEW_PATH(mode, seed, near)                                                                       \
    {RAD_SCENE_DATA,                                                                                           \
     {{surfaceLights, surfaceLightEnds, lightOfPatch, info->surfaceLightCount},                                \
      {info->environment, environmentTexels, environmentRows, environmentColumns}},                            \
     elements, corners, elementIrradiance, vertexIndirect, vertexCaustic, caustics, mode, seed, info->lift, near}

/* Each sample is a short path. Mirrors, rough metals and glass (material.h) pass it on, reflected
 * or refracted, up to RAD_SPECULAR_BOUNCES times between diffuse surfaces; at a rough metal the
 * lights are sampled as at a diffuse surface, weighed against the lobe's own direction
 * (light_estimate.h), which then weighs what it finds likewise. At the first diffuse
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
 * RAD_GATHER_BOUNCES times, and reads the solution only where a ray lands far enough.
 *
 * The radiance the path brings back along -dir to origin, for sample `index` of the sequences
 * keyed by `pixel`; *traced counts its rays. A camera's path starts with start.face < 0 and
 * traces from origin. A lightmap texel's starts at a point of a surface (start: its face and
 * barycentrics, t = 0; origin: the point; dir: into the face's front) with white set: that
 * first point is shaded as a white diffuse surface of no emission, whatever its material or
 * normal map, so the path brings back E / pi there, E the irradiance about the face's normal
 * (engines apply their normal maps to the light they read). Elsewhere a normal map turns the
 * normal a surface reflects about (material.h: mapped_normal); the solution
 * read where a ray lands is about the faces' own normals. */
#define RAD_GATHER_BOUNCES 2u
inline float3 view_path_radiance(const ViewPath* v, float3 origin, float3 dir, Hit start, bool white, uint pixel,
                                 uint index, uint* traced) {
    float3 radiance = (float3)(0.0f);
    float3 weight = (float3)(1.0f);
    /* the density the last diffuse bounce or rough metal drew dir with; < 0: none (MIS off) */
    float cosinePdf = -1.0f;
    uint diffuse = 0u;       /* diffuse surfaces shaded so far */
    bool glossyRay = false;  /* the last shaded surface's specular layer drew dir */
    uint specularBounces = 0u;
    float travelled = 0.0f; /* since the last diffuse surface */
    /* Whether the path sampled the lights before: its shadow rays toward punctual lights crossed
     * thin panes straight on (shadow_ray.h), so a rough pane met after does not pass those lights
     * once more (light_estimate.h: lobe_two_sided). */
    bool sampledBefore = false;
    for (;;) {
        Hit hit = start;
        if (hit.face < 0) {
            hit = trace_closest(&v->scene.geometry, origin, dir);
            ++*traced;
        }
        start.face = -1;
        /* a cosine ray that passed mirrors or glass: the solution's caustic holds what it finds */
        const bool inCaustic = v->caustics != 0u && diffuse > 0u && specularBounces > 0u && !glossyRay;
        if (hit.face < 0) {
            if (!inCaustic) radiance += weight * environment_seen(&v->lights.env, dir, cosinePdf);
            break;
        }
        travelled += hit.t;
        __global const FaceInfo* face = &v->scene.geometry.faces[hit.face];
        float3 n = vload3(0, face->normal);
        const bool front = dot3(dir, n) < 0.0f;
        const bool whiteHere = white && diffuse == 0u; /* the lightmap texel's own point */
        const uint kind = whiteHere ? RAD_SPECULAR_NONE : material_kind(&v->scene, hit.face);
        const uint first = front ? face->frontPatch : face->backPatch;
        if (material_black_side(kind, first != RAD_NO_PATCH)) break;
        if (!front) n = -n;
        float3 rho, le;
        material_at(&v->scene, hit, &rho, &le);
        if (whiteHere) {
            rho = (float3)(1.0f);
            le = (float3)(0.0f);
        }
        /* the back of single-sided glass emits nothing (it emits, if at all, from its front);
         * after mirrors or glass, the caustic holds the emission found */
        if (first != RAD_NO_PATCH && !inCaustic)
            radiance += weight * emission_seen(&v->scene, &v->lights.surface, hit, first, le, cosinePdf, -dot3(dir, n));
        if (inCaustic) break; /* nothing more for this ray to find */
        const float3 p = origin + hit.t * dir;
        const float off = ray_offset(origin, p, v->lift);
        if (!material_is_diffuse(kind)) {
            if (specularBounces >= RAD_SPECULAR_BOUNCES) break;
            const uint bounceKey = (diffuse << 8) | (specularBounces << 3);
            /* Where the surface has a lobe (a rough metal), light sampling, as at a diffuse
             * surface; not on a cosine ray from a shaded point when the solution's caustic holds
             * what reaches that point by way of it (and the ray then ends where it lands). */
            Lobe lobe;
            const bool sampled = material_samples_lights(&v->scene, hit.face, kind, front) &&
                                 !(v->caustics != 0u && diffuse > 0u && !glossyRay);
            if (sampled) {
                lobe = specular_lobe(&v->scene, hit, dir, vload3(0, face->normal));
                lobe.behind = p - off * n;
                if (sampledBefore && lobe.behindLights != RAD_BEHIND_NONE) lobe.behindLights = RAD_BEHIND_SURFACES;
                sampledBefore = true;
                radiance += weight * direct_light(&v->scene, &v->lights, &lobe, p + off * n, v->lift, v->seed, pixel,
                                                  bounceKey | RAD_KEY_GLOSSY_LIGHT, bounceKey | RAD_KEY_GLOSSY_MAP,
                                                  index, traced);
            }
            const uint4 u = path_sample(v->seed, pixel, bounceKey | RAD_KEY_SPECULAR, index);
            float3 carried;
            bool through;
            const float3 drawn = (float3)(unit_float(u.x), unit_float(u.y), unit_float(u.z));
            dir = specular_step(&v->scene, hit, dir, drawn, v->lift, false, &origin, &carried, &through);
            weight *= carried;
            if (!(fmax(fmax(weight.x, weight.y), weight.z) > 0.0f)) break;
            cosinePdf = sampled ? lobe_density(&lobe, dir) : -1.0f; /* weighs what dir finds */
            ++specularBounces;
            continue;
        }
        if (diffuse > 0u) { /* a gather ray's landing point */
            if (v->mode == RAD_VIEW_DIRECT && !glossyRay) break;
            if (!(travelled < v->near) || diffuse > RAD_GATHER_BOUNCES) {
                radiance += weight * solution_reflected(&v->scene, v->elements, v->elementIrradiance, hit, dir);
                break;
            }
        }
        const float3 q = p + off * n;
        const uint key = diffuse << 8;
#ifdef RAD_LAYERS
        const bool layered = !whiteHere && material_layered(&v->scene, hit.face);
        const Lobe lobe = layered ? layered_lobe(&v->scene, hit, dir, vload3(0, face->normal), rho)
                                  : surface_diffuse_lobe(&v->scene, hit, rho, n, front, !whiteHere);
#else
        const Lobe lobe = surface_diffuse_lobe(&v->scene, hit, rho, n, front, !whiteHere);
#endif
        sampledBefore = true;
        float3 reflected = direct_light(&v->scene, &v->lights, &lobe, q, v->lift, v->seed, pixel,
                                        key | RAD_KEY_SURFACE_LIGHT, key | RAD_KEY_MAP, index, traced);
        if (v->mode == RAD_VIEW_DIRECT || v->caustics != 0u) {
            const ElementPoint at = element_point(&v->scene.geometry, v->elements, v->corners, hit, first, front);
            float3 e = (float3)(0.0f);
            if (v->mode == RAD_VIEW_DIRECT) e += interpolate_vertices(v->vertexIndirect, at);
            if (v->caustics != 0u) e += interpolate_vertices(v->vertexCaustic, at);
            reflected += lobe.colour * e * (1.0f / RAD_PI);
        }
        radiance += weight * reflected;
        /* The cosine ray: the cosine's density cancels the cosine and 1 / pi of the BRDF. Under a
         * specular layer, that or the layer's direction, one drawn by its share of the albedo; a
         * ray the layer drew reads the solution where it lands in either mode (the elements'
         * indirect light of direct mode is the diffuse part's alone) and follows mirrors and
         * glass (the solution's caustic is the diffuse part's too). */
        const uint4 u = path_sample(v->seed, pixel, key | RAD_KEY_COSINE, index);
        glossyRay = false;
#ifdef RAD_LAYERS
        if (layered) {
            float3 carried;
            dir = layered_scatter(&lobe, unit_float(u.z), (float2)(unit_float(u.x), unit_float(u.y)), &carried,
                                  &cosinePdf, &glossyRay);
            weight *= carried;
        } else
#endif
        {
            dir = diffuse_scatter(&lobe, (float2)(unit_float(u.x), unit_float(u.y)), &cosinePdf);
            weight *= rho;
#ifdef RAD_NORMAL_MAPS
            if (!(dot3(dir, n) > 0.0f)) break; /* a normal map's cosine drew it into the face */
#endif
        }
        origin = q;
        if (!(fmax(fmax(weight.x, weight.y), weight.z) > 0.0f)) break;
        ++diffuse;
        specularBounces = 0u;
        travelled = 0.0f;
    }
    return radiance;
}

#endif
