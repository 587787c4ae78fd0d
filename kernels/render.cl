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
#include "environment.h"
#include "material.h"
#include "specular_walk.h"

/* A textured face's radiance at a hit: Le(uv) + rho(uv) H / pi (material.h: material_at), H
 * interpolated over the element from vertexIrradiance, the light arriving at its vertices. */
inline float3 textured_radiance(const SceneData* scene, __global const float4* vertexIrradiance, Hit hit,
                                ElementPoint at) {
    float3 rho, le;
    material_at(scene, hit, &rho, &le);
    return le + material_solution_reflectance(scene, hit, rho) * interpolate_vertices(vertexIrradiance, at) *
                    (1.0f / RAD_PI);
}

/* What a sample shows where it lands: the solution's radiance interpolated over the element (or
 * with showTextures, a textured face at pixel resolution), the environment where it leaves. */
inline float3 radiance_at(const SceneData* scene, __global const ElementNode* elements, __global const uint4* corners,
                          __global const float4* vertexRadiance, __global const float4* vertexIrradiance,
                          uint showTextures, Hit hit, float3 dir, const Environment* env, uint wireframe) {
    if (hit.face < 0) return environment_radiance(env, dir);
    __global const FaceInfo* face = &scene->geometry.faces[hit.face];
    const bool front = dot3(dir, vload3(0, face->normal)) < 0.0f;
    const uint first = front ? face->frontPatch : face->backPatch;
    if (first == RAD_NO_PATCH) return (float3)(0.0f);
    const ElementPoint at = element_point(&scene->geometry, elements, corners, hit, first, front);
    __global const FaceTexture* textures = &scene->faceTextures[showTextures != 0u ? hit.face : 0];
    const float3 radiance = showTextures != 0u &&
                                    (textures->baseSlot >= 0 || textures->emissiveSlot >= 0 || textures->coloured != 0u)
                                ? textured_radiance(scene, vertexIrradiance, hit, at)
                                : interpolate_vertices(vertexRadiance, at);
    /* The mesh view: a dark band along every element edge (a fixed share of the element). */
    const float3 w = at.weights;
    if (wireframe != 0u && fmin(w.x, fmin(w.y, w.z)) < 0.04f) return 0.05f * radiance;
    return radiance;
}

/* image[y * width + x]: the mean radiance over samplesAcross x samplesDown stratified, jittered
 * samples (a grid of that many columns and rows over the pixel, one sample in each cell). */
__kernel void render(RAD_KERNEL_PARAMS(RAD_RENDER_KERNEL)) {
    const uint pixel = get_global_id(0);
    if (pixel >= width * height) return;
    const SceneData scene = RAD_SCENE_DATA;
    const Environment env = scene_environment(&scene);
    const float lift = scene.about.lift;
    const uint x = pixel % width, y = pixel / width;
    float3 sum = (float3)(0.0f);
    for (uint sy = 0u; sy < samplesDown; ++sy)
        for (uint sx = 0u; sx < samplesAcross; ++sx) {
            const uint jitter = rad_hash2(pixel, sy * samplesAcross + sx);
            const float jx = unit_float(jitter), jy = unit_float(rad_hash(jitter));
            const float px = ((float)x + ((float)sx + jx) / (float)samplesAcross) / (float)width;
            const float py = ((float)y + ((float)sy + jy) / (float)samplesDown) / (float)height;
            float3 origin;
            const float3 dir = camera_ray(&camera, px, py, &origin);
            /* A sample that meets mirrors or glass follows them (specular_walk.h) to the surface
             * or sky they show, up to RAD_SPECULAR_BOUNCES in a row, adding what they emit
             * themselves; its weight is what they pass on (0: black, as a mirror's back without
             * patches, or past the limit). */
            SpecularWalk walk = specular_walk_from(&scene, origin, dir);
#ifdef RAD_SPECULAR_TRANSPORT
            walk_specular(&scene, &walk, RAD_SPECULAR_BOUNCES, rad_hash(jitter ^ 0x7f4a7c15u), lift, true, 0);
            sum += walk.glow;
            if (fmax(fmax(walk.weight.x, walk.weight.y), walk.weight.z) > 0.0f)
                sum += walk.weight * radiance_at(&scene, elements, corners, vertexRadiance, vertexIrradiance,
                                                 showTextures, walk.hit, walk.dir, &env, wireframe);
#else
            sum += radiance_at(&scene, elements, corners, vertexRadiance, vertexIrradiance, showTextures, walk.hit,
                               walk.dir, &env, wireframe);
#endif
        }
    image[pixel] = (float4)(sum / (float)(samplesAcross * samplesDown), 1.0f);
}
