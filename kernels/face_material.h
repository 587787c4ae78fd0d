/* A face's diffuse reflectance and emitted radiance at a hit, as the path tracer and the camera
 * pass's direct light read them: the face's (its front patch's) values, or where the face has a
 * texture, the material's factors times the texture at the hit (texture.h). */
#ifndef RADIOSITY_FACE_MATERIAL_H
#define RADIOSITY_FACE_MATERIAL_H

#include "bvh_traverse.h"
#include "texture.h"

inline void material_at(const SceneData* scene, Hit hit, float3* rho, float3* le) {
    __global const FaceMaterial* m = &scene->faceMaterials[hit.face];
    *le = vload3(0, m->emission);
    *rho = vload3(0, m->reflectance);
    if (scene->info->textured == 0u) return;
    __global const FaceTexture* ft = &scene->faceTextures[hit.face];
    const float b0 = 1.0f - hit.b1 - hit.b2;
    if (ft->baseSlot >= 0) {
        const float2 uv = b0 * vload2(0, ft->baseUv) + hit.b1 * vload2(1, ft->baseUv) + hit.b2 * vload2(2, ft->baseUv);
        *rho = vload3(0, ft->reflectance) *
               sample_texture(scene->texels, scene->srgb, &scene->textureSlots[ft->baseSlot], uv);
    }
    if (ft->emissiveSlot >= 0) {
        const float2 uv = b0 * vload2(0, ft->emissiveUv) + hit.b1 * vload2(1, ft->emissiveUv) +
                          hit.b2 * vload2(2, ft->emissiveUv);
        *le = vload3(0, ft->emission) *
              sample_texture(scene->texels, scene->srgb, &scene->textureSlots[ft->emissiveSlot], uv);
    }
}

#endif
