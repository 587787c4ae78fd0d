/* The camera pass: radiance seen through each pixel, from the radiosity solution. A few
 * stratified samples per pixel trace into the same BVH as the solver; at a hit, the radiance
 * B / pi is interpolated linearly over the element it lands on from the element's corners'
 * values (vertex radiance: planes fitted to the elements around each vertex, with T-vertices
 * held to their coarse edge, host/mesh/vertices.h), so shading is continuous within a surface
 * and never blends across surfaces or creases. Rays that miss see the sky or the environment map
 * (environment.h; black without either);
 * rays that hit the black back of a single-sided face see black. Where the scene has mirrors
 * and glass (-DRAD_SPECULAR_TRANSPORT), samples follow them to what they show. */
#pragma OPENCL FP_CONTRACT OFF

#include "kernel_args.h"
#include "rng.h"
#include "vector_math.h"
#include "bvh_traverse.h"
#include "solution_lookup.h"
#include "camera.h" /* camera_ray: the path tracer maps pixels to rays by the same code */
#include "texture.h"
#include "environment.h"
#include "specular.h"

/* Textures (faces whose material has any): the texels, their slots, the faces' texture
 * coordinates and factors, and the light arriving at each vertex. */
typedef struct {
    __global const FaceTexture* faces;
    __global const TextureSlot* slots;
    __global const uint* texels;
    __global const float* srgb;
    __global const float4* vertexIrradiance;
    uint present;
} Texturing;

/* A textured face's radiance at a hit: Le(uv) + rho(uv) H / pi, H interpolated over the element
 * from the light arriving at its corners (w: the element-corner weights). */
inline float3 textured_radiance(const Texturing* t, __global const FaceTexture* face, Hit hit, uint4 c, float3 w) {
    const float b0 = 1.0f - hit.b1 - hit.b2;
    float3 rho = vload3(0, face->reflectance), le = vload3(0, face->emission);
    if (face->baseSlot >= 0) {
        const float2 uv = b0 * vload2(0, face->baseUv) + hit.b1 * vload2(1, face->baseUv) + hit.b2 * vload2(2, face->baseUv);
        rho *= sample_texture(t->texels, t->srgb, &t->slots[face->baseSlot], uv);
    }
    if (face->emissiveSlot >= 0) {
        const float2 uv = b0 * vload2(0, face->emissiveUv) + hit.b1 * vload2(1, face->emissiveUv) +
                          hit.b2 * vload2(2, face->emissiveUv);
        le *= sample_texture(t->texels, t->srgb, &t->slots[face->emissiveSlot], uv);
    }
    const float3 h = w.x * t->vertexIrradiance[c.x].xyz + w.y * t->vertexIrradiance[c.y].xyz +
                     w.z * t->vertexIrradiance[c.z].xyz;
    return le + rho * h * (1.0f / RAD_PI);
}

inline float3 radiance_at(const SceneData* scene, __global const ElementNode* elements, __global const uint4* corners,
                          __global const float4* vertexRadiance, const Texturing* texturing, Hit hit, float3 dir,
                          const Environment* env, uint wireframe) {
    if (hit.face < 0) return environment_radiance(env, dir);
    __global const FaceInfo* face = &scene->faces[hit.face];
    const bool front = dot3(dir, vload3(0, face->normal)) < 0.0f;
    const uint first = front ? face->frontPatch : face->backPatch;
    if (first == RAD_NO_PATCH) return (float3)(0.0f);
    const ElementPoint at = element_point(scene, elements, corners, hit, first, front);
    __global const FaceTexture* textures = &texturing->faces[texturing->present ? hit.face : 0];
    const float3 radiance = texturing->present && (textures->baseSlot >= 0 || textures->emissiveSlot >= 0)
                                ? textured_radiance(texturing, textures, hit, at.corners, at.weights)
                                : interpolate_vertices(vertexRadiance, at);
    /* The mesh view: a dark band along every element edge (a fixed share of the element). */
    const float3 w = at.weights;
    if (wireframe != 0u && fmin(w.x, fmin(w.y, w.z)) < 0.04f) return 0.05f * radiance;
    return radiance;
}

#ifdef RAD_SPECULAR_TRANSPORT
/* A sample that meets mirrors or glass follows them (specular.h) to the surface or sky they
 * show, up to RAD_SPECULAR_BOUNCES in a row; at glass it reflects or refracts by a choice drawn
 * per sample against the Fresnel reflectance. *weight: what the surfaces pass on (0: black, as
 * a mirror's back without patches, or past the bounce limit); *glow: what they emit themselves
 * (the face's emission, from a side with patches), as weighed. Returns the hit it ends on. */
inline Hit follow_specular(const SceneData* scene, float lift, uint key, float3 org, Hit hit, float3* dir,
                           float3* weight, float3* glow) {
    for (uint bounce = 0u; hit.face >= 0; ++bounce) {
        __global const SpecularFace* surface = &scene->specular[hit.face];
        if (surface->kind == RAD_SPECULAR_NONE) break;
        __global const FaceInfo* face = &scene->faces[hit.face];
        const float3 ng = vload3(0, face->normal);
        const bool front = dot3(*dir, ng) < 0.0f;
        const bool patched = (front ? face->frontPatch : face->backPatch) != RAD_NO_PATCH;
        if (patched) *glow += *weight * vload3(0, scene->faceMaterials[hit.face].emission);
        if (bounce == RAD_SPECULAR_BOUNCES || specular_black(surface, patched)) {
            *weight = (float3)(0.0f);
            break;
        }
        float3 carried;
        *dir = specular_continue(surface, hit, *dir, ng, front, specular_choice(key, bounce), lift, &org,
                                 &carried);
        *weight *= carried;
        hit = trace_closest(scene, org, *dir);
    }
    return hit;
}
#endif

/* image[y * width + x]: the mean radiance over samplesPerSide^2 stratified, jittered samples. */
__kernel void render(RAD_KERNEL_PARAMS(RAD_RENDER_KERNEL)) {
    const uint pixel = get_global_id(0);
    if (pixel >= width * height) return;
    const SceneData scene = RAD_SCENE_DATA;
    const Texturing texturing = {faceTextures, textureSlots, texels, srgb, vertexIrradiance, showTextures};
    const Environment env = scene_environment(&scene);
    const float lift = scene.info->lift;
    const uint x = pixel % width, y = pixel / width;
    float3 sum = (float3)(0.0f);
    for (uint sy = 0u; sy < samplesPerSide; ++sy)
        for (uint sx = 0u; sx < samplesPerSide; ++sx) {
            const uint jitter = rad_hash2(pixel, sy * samplesPerSide + sx);
            const float jx = unit_float(jitter), jy = unit_float(rad_hash(jitter));
            const float px = ((float)x + ((float)sx + jx) / (float)samplesPerSide) / (float)width;
            const float py = ((float)y + ((float)sy + jy) / (float)samplesPerSide) / (float)height;
            float3 origin;
            float3 dir = camera_ray(&camera, px, py, &origin);
            Hit hit = trace_closest(&scene, origin, dir);
#ifdef RAD_SPECULAR_TRANSPORT
            float3 weight = (float3)(1.0f), glow = (float3)(0.0f);
            hit = follow_specular(&scene, lift, rad_hash(jitter ^ 0x7f4a7c15u), origin, hit, &dir, &weight, &glow);
            sum += glow;
            if (fmax(fmax(weight.x, weight.y), weight.z) > 0.0f)
                sum += weight *
                       radiance_at(&scene, elements, corners, vertexRadiance, &texturing, hit, dir, &env, wireframe);
#else
            sum += radiance_at(&scene, elements, corners, vertexRadiance, &texturing, hit, dir, &env, wireframe);
#endif
        }
    image[pixel] = (float4)(sum / (float)(samplesPerSide * samplesPerSide), 1.0f);
}
