/* The scattering layer: what a surface does with light, for every pass that scatters it (the
 * progressive solve's shots, the direct light on elements, the camera pass, the lightmap, the
 * path tracer). The passes ask the questions below and never test a material's kind
 * themselves, so a new kind of surface is a change to this file (and to the host's
 * scene/material_model.h and device/specular_faces.cpp, which say which faces are of it).
 *
 * The kinds (SpecularFace, shared_types.h; RAD_SPECULAR_NONE for a face that has none):
 *   diffuse      Lambert's law, reflectance rho (the face's, or its texture at the hit); the
 *                radiosity pass carries its light (its patches shoot what they reflect);
 *   mirror       reflection about the shading normal, Schlick's Fresnel from F0 = colour;
 *   rough metal  glTF's GGX microfacet reflection (ggx.h), alpha = roughness^2, the same Fresnel,
 *                scaled to give back what single scattering loses (ggx_energy);
 *   glass        the dielectric Fresnel from its IOR picks reflection or transmission; the
 *                transmitted light is tinted by colour (as it enters a solid, at every crossing of
 *                a thin pane), refracted by a solid, straight through a thin pane; inside a solid
 *                it is attenuated by the length it travels (medium_transmittance);
 *   retroreflector  light goes back the way it came, times colour (a kind for tests: no glTF
 *                material maps to it).
 * A diffuse face may carry glTF's specular layer (FaceLayer, shared_types.h; programs built with
 * -DRAD_LAYERS): a GGX lobe over its diffuse colour, which the camera pass, the lightmap's texels
 * and the path tracer draw as one lobe of two parts (layered_lobe below); the radiosity pass
 * reflects the layer's light diffusely (material_solution_reflectance).
 * Every kind but diffuse has no diffuse reflectance in the radiosity pass (the host gives its
 * patches none: reflectanceBesideSpecular, host/prepared/patch_system.h): rays carry the light
 * it passes on instead (specular_walk.h), and what it keeps (material_keeps) is absorbed there.
 *
 * The shading normal (interpolated from a face's corners, so a sphere of flat faces reflects as a
 * sphere) decides the directions; where it would send a ray to the wrong side of the surface, the
 * face's own normal does. */
#ifndef RADIOSITY_MATERIAL_H
#define RADIOSITY_MATERIAL_H

#include "bvh_traverse.h"
#include "ggx.h"
#include "rng.h"
#include "sampling.h"
#include "texture.h"
#include "vector_math.h"

/* ---- What each kind does ---- */

/* The kind of face `face`: RAD_SPECULAR_NONE (diffuse) unless the scene has mirrors or glass
 * (programs built with -DRAD_SPECULAR_TRANSPORT: host/device/device_scene.h). */
inline uint material_kind(const SceneData* scene, int face) {
#ifdef RAD_SPECULAR_TRANSPORT
    return scene->geometry.specular[face].kind;
#else
    return RAD_SPECULAR_NONE;
#endif
}

/* Whether the radiosity pass carries its light (a diffuse surface) rather than rays (the rest). */
inline bool material_is_diffuse(uint kind) {
    return kind == RAD_SPECULAR_NONE;
}

/* Whether light passes through it, so that neither side is black (glass). */
inline bool material_transmits(uint kind) {
    return kind == RAD_SPECULAR_GLASS || kind == RAD_SPECULAR_THIN_GLASS;
}

/* Whether light sampling applies where a path meets it: it scatters into a lobe a light sample
 * can be weighed against (diffuse, rough metal), not into single directions (mirror, glass). */
inline bool material_has_lobe(uint kind) {
    return kind == RAD_SPECULAR_NONE || kind == RAD_SPECULAR_GLOSSY;
}

/* Whether light sampling applies where a path meets face `face` of kind `kind` (from its front
 * side or not): at a lobe (material_has_lobe), and at rough glass (specular_lobe), but not from
 * inside a solid, whose own faces hold the lights outside from its shadow rays (and whose medium
 * would attenuate them). */
inline bool material_samples_lights(const SceneData* scene, int face, uint kind, bool front) {
#ifdef RAD_SPECULAR_TRANSPORT
    if (material_transmits(kind))
        return scene->geometry.specular[face].alpha > 0.0f && (front || kind == RAD_SPECULAR_THIN_GLASS);
#endif
    return material_has_lobe(kind);
}

/* Whether shadow rays cross it, passing what material_pane_transmittance says (a thin pane: a
 * window lets the sun in). */
inline bool material_crossed_by_shadow_rays(uint kind) {
    return kind == RAD_SPECULAR_THIN_GLASS;
}

/* Whether a ray that meets the side of a face without patches (`patched` false: a single-sided
 * face's back) ends there, black: every kind that does not transmit. */
inline bool material_black_side(uint kind, bool patched) {
    return !patched && !material_transmits(kind);
}

/* ---- The diffuse part: reflectance and emission at a hit ---- */

/* A face's diffuse reflectance and emitted radiance at a hit: the face's (its front patch's)
 * values, or where the face has a texture or vertex colours, the material's factors times the
 * texture and the colours interpolated there. */
inline void material_at(const SceneData* scene, Hit hit, float3* rho, float3* le) {
    __global const FaceMaterial* m = &scene->faceMaterials[hit.face];
    *le = vload4(0, m->emission).xyz; /* one aligned load each (w unused) */
    *rho = vload4(0, m->reflectance).xyz;
    if (scene->about.textured == 0u) return;
    __global const FaceTexture* ft = &scene->faceTextures[hit.face];
    const float b0 = 1.0f - hit.b1 - hit.b2;
    if (ft->baseSlot >= 0) {
        const float2 uv = b0 * vload2(0, ft->baseUv) + hit.b1 * vload2(1, ft->baseUv) + hit.b2 * vload2(2, ft->baseUv);
        *rho = vload3(0, ft->reflectance) *
               sample_texture(scene->geometry.texels, scene->srgb, &scene->geometry.textureSlots[ft->baseSlot], uv);
    }
    if (ft->coloured != 0u) {
        const float3 colour = b0 * vload3(0, ft->colours) + hit.b1 * vload3(0, ft->colours + 4) +
                              hit.b2 * vload3(0, ft->colours + 8);
        *rho = (ft->baseSlot >= 0 ? *rho : vload3(0, ft->reflectance)) * colour;
    }
    if (ft->emissiveSlot >= 0) {
        const float2 uv = b0 * vload2(0, ft->emissiveUv) + hit.b1 * vload2(1, ft->emissiveUv) +
                          hit.b2 * vload2(2, ft->emissiveUv);
        *le = vload3(0, ft->emission) *
              sample_texture(scene->geometry.texels, scene->srgb, &scene->geometry.textureSlots[ft->emissiveSlot], uv);
    }
}

/* The three uniform numbers a ray's `bounce`-th scattering draws from, from a per-ray key: the
 * first picks smooth glass's reflection or transmission, the first two a rough metal's or rough
 * glass's microfacet normal, the third rough glass's choice. */
inline float3 specular_choice(uint key, uint bounce) {
    return (float3)(unit_float(rad_hash2(key, bounce)), unit_float(rad_hash2(key ^ 0x68e31da4u, bounce)),
                    unit_float(rad_hash2(key ^ 0x2c1b3c6du, bounce)));
}

/* ---- Fresnel and normals ---- */

/* The dielectric Fresnel reflectance for a ray meeting the surface at cosine cosi > 0 from the
 * side where the ratio of indices (this side's over the other's) is eta; 1 beyond the critical
 * angle. *cost: the cosine of the transmitted ray. */
inline float dielectric_fresnel(float cosi, float eta, float* cost) {
    const float sin2t = eta * eta * fmax(0.0f, 1.0f - cosi * cosi);
    if (sin2t >= 1.0f) {
        *cost = 0.0f;
        return 1.0f;
    }
    const float ct = sqrt(1.0f - sin2t);
    const float rs = (eta * cosi - ct) / (eta * cosi + ct);
    const float rp = (eta * ct - cosi) / (eta * ct + cosi);
    *cost = ct;
    return 0.5f * (rs * rs + rp * rp);
}

/* Schlick's Fresnel reflectance of a mirror of normal-incidence reflectance f0 at cosine cosi. */
inline float3 mirror_fresnel(float3 f0, float cosi) {
    const float m = 1.0f - cosi, m2 = m * m;
    return f0 + (1.0f - f0) * (m2 * m2 * m);
}

/* The normal that reflects and refracts a ray along dir at a hit (front normal *ng), from the
 * face's corners' shading normals (normals: three of four floats each):
 * the shading normal, or the face's own where the shading normal would send the ray to the wrong
 * side; both turned toward the side the ray comes from (*ng too). *cosi: its cosine with -dir. */
inline float3 shading_normal(__global const float* normals, Hit hit, float3 dir, float3* ng, float* cosi) {
    const float b0 = 1.0f - hit.b1 - hit.b2;
    float3 ns = b0 * vload3(0, normals) + hit.b1 * vload3(0, normals + 4) + hit.b2 * vload3(0, normals + 8);
    ns = normalize3(ns);
    if (!(dot3(dir, *ng) < 0.0f)) { /* both toward the side the ray comes from */
        *ng = -*ng;
        ns = -ns;
    }
    *cosi = -dot3(dir, ns);
    if (!(*cosi > 0.0f) || !(dot3(ns, *ng) > 0.0f)) {
        ns = *ng;
        *cosi = -dot3(dir, *ng);
    }
    return ns;
}

#ifdef RAD_NORMAL_MAPS
/* The normal face hit.face's normal map (FaceNormalMap) gives at the hit, turned to the side of
 * n (the face's normal on the side the ray came from; `front`: that is the front): true where
 * the face has a map and the normal it gives leans less than 90 degrees from n (else the face is
 * shaded without it). The frame is the corners' normals and tangents interpolated, the tangent
 * made perpendicular to the normal (Gram-Schmidt), as glTF viewers build it. */
inline bool mapped_normal(const SceneData* scene, Hit hit, float3 n, bool front, float3* mapped) {
    __global const FaceNormalMap* f = &scene->faceNormalMaps[hit.face];
    if (f->slot < 0) return false;
    const float b0 = 1.0f - hit.b1 - hit.b2;
    const float3 ns = normalize3(b0 * vload3(0, &f->normals[0][0]) + hit.b1 * vload3(0, &f->normals[1][0]) +
                                 hit.b2 * vload3(0, &f->normals[2][0]));
    float3 t = b0 * vload3(0, &f->tangents[0][0]) + hit.b1 * vload3(0, &f->tangents[1][0]) +
               hit.b2 * vload3(0, &f->tangents[2][0]);
    t -= ns * dot3(ns, t);
    const float tl = sqrt(dot3(t, t));
    if (!(tl > 1e-6f)) return false;
    t *= 1.0f / tl;
    const float sign = (b0 * f->tangents[0][3] + hit.b1 * f->tangents[1][3]) + hit.b2 * f->tangents[2][3];
    const float3 b = sign < 0.0f ? -cross3(ns, t) : cross3(ns, t);
    const float2 uv = b0 * vload2(0, f->uv) + hit.b1 * vload2(1, f->uv) + hit.b2 * vload2(2, f->uv);
    const float3 texel = sample_texture(scene->geometry.texels, scene->srgb, &scene->geometry.textureSlots[f->slot], uv);
    const float3 c = 2.0f * texel - 1.0f;
    float3 m = (c.x * f->scale) * t + (c.y * f->scale) * b + c.z * ns;
    const float ml = sqrt(dot3(m, m));
    if (!(ml > 1e-6f)) return false;
    m *= front ? 1.0f / ml : -1.0f / ml;
    if (!(dot3(m, n) > 1e-4f)) return false;
    *mapped = m;
    return true;
}
#endif

/* shading_normal for the mirror's, rough metal's or glass's face hit.face, or its normal map's
 * normal (mapped_normal) where it has one and the ray sees the side it turns to; *ng and the
 * normal toward the side the ray comes from. */
inline float3 specular_normal(const SceneData* scene, Hit hit, float3 dir, float3* ng, float* cosi) {
    __global const SpecularFace* f = &scene->geometry.specular[hit.face];
#ifdef RAD_NORMAL_MAPS
    const bool front = dot3(dir, *ng) < 0.0f;
#endif
    float3 ns = shading_normal(&f->normals[0][0], hit, dir, ng, cosi);
#ifdef RAD_NORMAL_MAPS
    float3 m;
    if (mapped_normal(scene, hit, *ng, front, &m) && -dot3(dir, m) > 0.0f) {
        ns = m;
        *cosi = -dot3(dir, m);
    }
#endif
    return ns;
}

/* ---- The GGX lobes' albedo (host/scene/ggx_albedo.h), where a layer or a rough metal needs it ---- */

#ifdef RAD_GGX_TABLE
/* The lobe's albedo factors (E1, E5) toward a direction of cosine mu at roughness r, from the
 * host's table (host/scene/ggx_albedo.h), bilinear in sqrt(mu) and r, clamped, as the host reads it. */
inline float2 layer_albedo(__global const float* table, float mu, float r) {
    const float x = sqrt(clamp(mu, 0.0f, 1.0f)) * (float)(RAD_ALBEDO_COSINES - 1u);
    const float y = clamp(r, 0.0f, 1.0f) * (float)(RAD_ALBEDO_ROUGHNESS - 1u);
    const uint i = min((uint)x, RAD_ALBEDO_COSINES - 2u), j = min((uint)y, RAD_ALBEDO_ROUGHNESS - 2u);
    const float fx = x - (float)i, fy = y - (float)j;
    const uint row = j * RAD_ALBEDO_COSINES + i;
    const float2 a = vload2(row, table), b = vload2(row + 1u, table);
    const float2 c = vload2(row + RAD_ALBEDO_COSINES, table), d = vload2(row + RAD_ALBEDO_COSINES + 1u, table);
    return (1.0f - fy) * ((1.0f - fx) * a + fx * b) + fy * ((1.0f - fx) * c + fx * d);
}

/* The same factors averaged over the hemisphere (2 integral E mu dmu), linear in r: the table's
 * last rows. */
inline float2 layer_average(__global const float* table, float r) {
    const float y = clamp(r, 0.0f, 1.0f) * (float)(RAD_ALBEDO_ROUGHNESS - 1u);
    const uint j = min((uint)y, RAD_ALBEDO_ROUGHNESS - 2u);
    const float fy = y - (float)j;
    const uint at = RAD_ALBEDO_COSINES * RAD_ALBEDO_ROUGHNESS + j;
    return (1.0f - fy) * vload2(at, table) + fy * vload2(at + 1u, table);
}

/* What a GGX lobe of roughness r, Fresnel factor f0 + (f90 - f0) (1 - c)^5 is scaled by, per
 * channel, toward a viewer at cosine mu, so that it reflects the light single scattering loses
 * (host/scene/ggx_albedo.h: ggxEnergyScale, Cycles' "Multiscatter GGX"): 1 + Fms (1 - E1) / E1,
 * from E1 there and its hemispherical mean (ggx_energy_at). */
inline float3 ggx_energy_at(float e1, float average, float3 f0, float f90) {
    const float3 favg = f0 + (f90 - f0) * (1.0f / 21.0f);
    const float3 fms = favg * average / (1.0f - favg * (1.0f - average));
    return 1.0f + fms * ((1.0f - e1) / fmax(e1, 1e-3f));
}

inline float3 ggx_energy(__global const float* table, float mu, float r, float3 f0, float f90) {
    return ggx_energy_at(layer_albedo(table, mu, r).x, layer_average(table, r).x, f0, f90);
}

#endif

/* ---- Lobes: what light sampling evaluates (diffuse surfaces, rough metals) ---- */

/* A surface's lobe where a ray along dir met it: a diffuse one (reflectance `colour` about n), a
 * rough metal's (F0 `colour`, GGX alpha, about the shading normal n, with the frame (t, b, n),
 * the face's normal ng toward the ray's side and wo, toward where the ray came from, in that
 * frame), or a layered one (RAD_LOBE_LAYERED): a diffuse part of reflectance `colour` about nd
 * (ng, or a normal map's normal; already times the share the layer leaves toward wo) and a GGX
 * part about n with the Fresnel factor f0 + (f90 - f0) (1 - c)^5, drawn with chance
 * `layerChance`. A diffuse lobe's n may be a normal map's (surface_diffuse_lobe): directions
 * below ng then count for nothing. `energy`: what a GGX part is scaled by (ggx_energy; 1 for a
 * diffuse lobe). */
#define RAD_LOBE_LAYERED 0x100u
#define RAD_BEHIND_NONE 0u
#define RAD_BEHIND_SURFACES 1u
#define RAD_BEHIND_ALL 2u
typedef struct {
    uint kind;
    float3 n, ng, t, b, wo, colour, energy;
    float alpha;
    float eta;     /* rough glass: the ratio of indices from the viewer's side */
    /* A thin rough pane passes the lights behind it: RAD_BEHIND_NONE, RAD_BEHIND_SURFACES (the
     * emitting surfaces and the environment) or RAD_BEHIND_ALL (the punctual lights too); its
     * shadow rays toward them leave from `behind`. */
    uint behindLights;
    float3 behind;
#ifdef RAD_LAYERS
    float3 f0, nd; /* nd: the diffuse part's normal (ng, or a normal map's) */
    float f90, layerChance;
#endif
} Lobe;

/* A diffuse surface of reflectance rho, lit on the side of unit normal n. */
inline Lobe diffuse_lobe(float3 rho, float3 n) {
    Lobe l;
    l.kind = RAD_SPECULAR_NONE;
    l.n = n;
    l.ng = n;
    l.t = l.b = (float3)(0.0f); /* unused: diffuse_scatter makes its frame when it draws */
    l.wo = (float3)(0.0f, 0.0f, 1.0f);
    l.colour = rho;
    l.energy = (float3)(1.0f);
    l.alpha = 1.0f;
    l.eta = 1.0f;
    l.behindLights = RAD_BEHIND_NONE;
    l.behind = (float3)(0.0f);
    return l;
}

/* A diffuse surface's lobe where a ray hit face hit.face (reflectance rho; n its normal on the
 * ray's side, `front` whether that is the front): about the normal its normal map gives there
 * (mapped_normal) where `mapped` and it has one, else about n. */
inline Lobe surface_diffuse_lobe(const SceneData* scene, Hit hit, float3 rho, float3 n, bool front, bool mapped) {
    Lobe l = diffuse_lobe(rho, n);
#ifdef RAD_NORMAL_MAPS
    float3 m;
    if (mapped && mapped_normal(scene, hit, n, front, &m)) l.n = m;
#endif
    return l;
}

/* ggx_energy for a rough metal (F0 f0, GGX alpha) seen at cosine cosi. */
inline float3 glossy_energy(const SceneData* scene, float3 f0, float alpha, float cosi) {
#ifdef RAD_GGX_TABLE
    return ggx_energy(scene->ggxAlbedo, cosi, sqrt(alpha), f0, 1.0f);
#else
    return (float3)(1.0f);
#endif
}

/* A rough metal's lobe (face hit.face) where a ray along dir hit it; ng: the face's front normal. */
inline Lobe glossy_lobe(const SceneData* scene, Hit hit, float3 dir, float3 ng) {
    __global const SpecularFace* f = &scene->geometry.specular[hit.face];
    Lobe l;
    float cosi;
    l.kind = RAD_SPECULAR_GLOSSY;
    l.ng = ng;
    l.n = specular_normal(scene, hit, dir, &l.ng, &cosi);
    frame_about(l.n, &l.t, &l.b);
    l.wo = (float3)(-dot3(dir, l.t), -dot3(dir, l.b), cosi);
    l.colour = vload3(0, f->colour);
    l.alpha = f->colour[3];
    l.eta = 1.0f;
    l.behindLights = RAD_BEHIND_NONE;
    l.behind = (float3)(0.0f);
    l.energy = glossy_energy(scene, l.colour, l.alpha, cosi);
    return l;
}

/* The lobe light sampling weighs at a rough metal (glossy_lobe) or rough glass (face hit.face,
 * met along dir; ng its front normal): glass's is what its microfacets reflect toward the
 * viewer's side, the GGX lobe with the dielectric Fresnel reflectance at eta, unscaled as
 * rough_glass_scatter's reflection is, drawn with that reflectance's chance, and for a thin pane
 * also what it passes to the other side, that reflection mirrored through the pane times
 * 1 - Fresnel and the tint `colour` (lobe_eval); the caller sets `behind` (and may narrow
 * `behindLights`). What a solid transmits (refracted) is not sampled: a path finds the lights
 * beyond it by meeting them, weight 1. */
inline Lobe specular_lobe(const SceneData* scene, Hit hit, float3 dir, float3 ng) {
    __global const SpecularFace* f = &scene->geometry.specular[hit.face];
    if (f->kind == RAD_SPECULAR_GLOSSY) return glossy_lobe(scene, hit, dir, ng);
    const bool front = dot3(dir, ng) < 0.0f;
    Lobe l;
    float cosi;
    l.kind = f->kind;
    l.ng = ng;
    l.n = specular_normal(scene, hit, dir, &l.ng, &cosi);
    frame_about(l.n, &l.t, &l.b);
    l.wo = (float3)(-dot3(dir, l.t), -dot3(dir, l.b), cosi);
    l.colour = vload3(0, f->colour); /* the tint */
    l.alpha = f->alpha;
    l.behindLights = f->kind == RAD_SPECULAR_THIN_GLASS ? RAD_BEHIND_ALL : RAD_BEHIND_NONE;
    l.behind = (float3)(0.0f);
    l.eta = f->kind == RAD_SPECULAR_THIN_GLASS || front ? 1.0f / f->colour[3] : f->colour[3];
    l.energy = (float3)(1.0f);
    return l;
}

#ifdef RAD_LAYERS
/* ---- The specular layer over a diffuse face (FaceLayer) ---- */

/* Whether face `face` has a specular layer. */
inline bool material_layered(const SceneData* scene, int face) {
    return scene->faceLayers[face].factors[3] > 0.0f;
}

/* glTF's Fresnel factor F0 + (F90 - F0) (1 - c)^5 at cosine c. */
inline float3 layer_fresnel(float3 f0, float f90, float c) {
    const float m = 1.0f - c, m2 = m * m;
    return f0 + (f90 - f0) * (m2 * m2 * m);
}

/* A layered face's material at a hit of base colour `base`: its diffuse part's colour, the
 * lobe's F0 and F90, the dielectric's (dF0, dF90) and the roughness, with metallic and roughness
 * from the metallicRoughnessTexture there where it has one, and the dielectric's F0 and F90 from
 * KHR_materials_specular's textures there where it has them (FaceLayer). */
typedef struct {
    float3 diffuse, f0, dielectricF0;
    float f90, dielectricF90, roughness;
} LayerAt;

#define RAD_SMOOTHEST_LAYER 0.05f /* host/scene/material_model.h: kSmoothestLayer */
inline LayerAt layer_at(const SceneData* scene, Hit hit, float3 base) {
    __global const FaceLayer* f = &scene->faceLayers[hit.face];
    float metallic = f->factors[0], roughness = f->factors[1];
    if (f->metalSlot >= 0) { /* blue: metallic, green: roughness */
        const float b0 = 1.0f - hit.b1 - hit.b2;
        const float2 uv = b0 * vload2(0, f->metalUv) + hit.b1 * vload2(1, f->metalUv) + hit.b2 * vload2(2, f->metalUv);
        const float3 mr = sample_texture(scene->geometry.texels, scene->srgb,
                                         &scene->geometry.textureSlots[f->metalSlot], uv);
        metallic *= mr.z;
        roughness *= mr.y;
    }
    LayerAt a;
    float4 dielectric = vload4(0, f->dielectric);
    if (f->specularTextures >= 0) { /* KHR_materials_specular's textures */
        __global const FaceSpecularTextures* t = &scene->faceSpecularTextures[f->specularTextures];
        const float b0 = 1.0f - hit.b1 - hit.b2;
        float4 specular = vload4(0, t->specular);
        if (t->colourSlot >= 0) {
            const float2 uv = b0 * vload2(0, t->colourUv) + hit.b1 * vload2(1, t->colourUv) + hit.b2 * vload2(2, t->colourUv);
            specular.xyz *= sample_texture(scene->geometry.texels, scene->srgb, &scene->geometry.textureSlots[t->colourSlot], uv);
        }
        if (t->strengthSlot >= 0) {
            const float2 uv =
                b0 * vload2(0, t->strengthUv) + hit.b1 * vload2(1, t->strengthUv) + hit.b2 * vload2(2, t->strengthUv);
            specular.w *= sample_alpha(scene->geometry.texels, &scene->geometry.textureSlots[t->strengthSlot], uv);
        }
        dielectric = (float4)(fmin(specular.xyz, (float3)(1.0f)) * specular.w, specular.w);
    }
    a.dielectricF0 = dielectric.xyz;
    a.dielectricF90 = dielectric.w;
    a.diffuse = base * ((1.0f - metallic) * f->factors[2]);
    a.f0 = (1.0f - metallic) * dielectric.xyz + metallic * base;
    a.f90 = (1.0f - metallic) * dielectric.w + metallic;
    a.roughness = fmax(roughness, RAD_SMOOTHEST_LAYER);
    return a;
}

/* The lobe of a face with a layer, where a ray along dir hit it (ng: the face's front normal),
 * its base colour `base` there: the diffuse part keeps 1 - Ed(wo) of its colour, Ed the
 * dielectric's albedo toward the ray's origin; the layer's part is drawn with a chance in
 * proportion to its albedo there (by luminance), the diffuse part with the rest. */
inline Lobe layered_lobe(const SceneData* scene, Hit hit, float3 dir, float3 ng, float3 base) {
    __global const FaceLayer* f = &scene->faceLayers[hit.face];
    const LayerAt at = layer_at(scene, hit, base);
    Lobe l;
    float cosi;
    l.kind = RAD_LOBE_LAYERED;
    l.ng = ng;
    const bool front = dot3(dir, ng) < 0.0f;
    l.n = shading_normal(&f->normals[0][0], hit, dir, &l.ng, &cosi);
    l.nd = l.ng;
#ifdef RAD_NORMAL_MAPS
    float3 m; /* a normal map shades both parts, where the ray sees the side it tilts */
    if (mapped_normal(scene, hit, l.ng, front, &m) && -dot3(dir, m) > 0.0f) {
        l.n = l.nd = m;
        cosi = -dot3(dir, m);
    }
#endif
    frame_about(l.n, &l.t, &l.b);
    l.wo = (float3)(-dot3(dir, l.t), -dot3(dir, l.b), cosi);
    l.alpha = at.roughness * at.roughness;
    const float2 e = layer_albedo(scene->ggxAlbedo, cosi, at.roughness);
    const float average = layer_average(scene->ggxAlbedo, at.roughness).x; /* the table read once for both scales */
    const float3 dielectric = ggx_energy_at(e.x, average, at.dielectricF0, at.dielectricF90) *
                              (at.dielectricF0 * e.x + (at.dielectricF90 - at.dielectricF0) * e.y);
    l.colour = at.diffuse * (1.0f - dielectric);
    l.f0 = at.f0;
    l.f90 = at.f90;
    l.energy = ggx_energy_at(e.x, average, at.f0, at.f90);
    const float3 albedo = l.energy * (at.f0 * e.x + (at.f90 - at.f0) * e.y);
    const float wl = (0.2126f * albedo.x + 0.7152f * albedo.y) + 0.0722f * albedo.z;
    const float wd = (0.2126f * l.colour.x + 0.7152f * l.colour.y) + 0.0722f * l.colour.z;
    l.layerChance = wl + wd > 0.0f ? wl / (wl + wd) : 0.0f;
    return l;
}

/* A layered lobe's two parts toward `toward`: f cos of the diffuse part (*diffuse) and of the
 * layer (*layer), and the density with which layered_scatter draws it by each part, times the
 * part's chance (*diffusePdf, *layerPdf); all 0 below the face. */
inline void layered_parts(const Lobe* l, float3 toward, float3* diffuse, float3* layer, float* diffusePdf,
                          float* layerPdf) {
    *diffuse = *layer = (float3)(0.0f);
    *diffusePdf = *layerPdf = 0.0f;
    if (!(dot3(toward, l->ng) > 0.0f)) return;
    const float cosine = fmax(dot3(toward, l->nd), 0.0f);
    *diffuse = l->colour * (cosine * (1.0f / RAD_PI));
    *diffusePdf = (1.0f - l->layerChance) * (cosine * (1.0f / RAD_PI));
    const float3 wi = (float3)(dot3(toward, l->t), dot3(toward, l->b), dot3(toward, l->n));
    float c;
    const float f = ggx_reflection(l->wo, wi, l->alpha, &c);
    if (!(f > 0.0f)) return;
    *layer = f * l->energy * layer_fresnel(l->f0, l->f90, c);
    *layerPdf = l->layerChance * ggx_reflection_pdf(l->wo, wi, l->alpha);
}

/* A light sample's weight through a layered lobe toward `toward`, drawn by the light with density
 * lightPdf: each part's f cos over lightPdf plus its own drawing density, the balance heuristic
 * with each part as a sampling technique of its own (the part a path's direction came from is
 * weighed the same way: layered_scatter's *pdf). */
inline float3 layered_light_weight(const Lobe* l, float3 toward, float lightPdf) {
    float3 diffuse, layer;
    float diffusePdf, layerPdf;
    layered_parts(l, toward, &diffuse, &layer, &diffusePdf, &layerPdf);
    return diffuse * (1.0f / (lightPdf + diffusePdf)) + layer * (1.0f / (lightPdf + layerPdf));
}

/* A direction off a layered lobe: with chance layerChance (against `choice`) from the layer's
 * visible normals, else cosine-distributed about the face; u draws it. *weight: what the path
 * carries on (the part's f cos over its density times its chance); *pdf: that density times the
 * chance, which weighs what the direction finds (< 0 where nothing goes on); *glossy: whether the
 * layer drew it. */
inline float3 layered_scatter(const Lobe* l, float choice, float2 u, float3* weight, float* pdf, bool* glossy) {
    *glossy = choice < l->layerChance;
    if (*glossy) {
        const float3 m = ggx_visible_normal(l->wo, l->alpha, u);
        const float om = dot3(l->wo, m);
        const float3 wi = (2.0f * om) * m - l->wo;
        const float3 out = normalize3(wi.x * l->t + wi.y * l->b + wi.z * l->n);
        if (!(wi.z > 0.0f) || !(dot3(out, l->ng) > 0.0f)) {
            *weight = (float3)(0.0f);
            *pdf = -1.0f;
            return out;
        }
        *weight = l->energy * layer_fresnel(l->f0, l->f90, om) * (ggx_masking_ratio(l->wo, wi, l->alpha) / l->layerChance);
        *pdf = l->layerChance * ggx_reflection_pdf(l->wo, wi, l->alpha);
        return out;
    }
    float3 t, b;
    frame_about(l->nd, &t, &b);
    const float3 w = cosine_hemisphere(u);
    const float keep = 1.0f - l->layerChance;
    const float3 out = w.x * t + w.y * b + w.z * l->nd;
#ifdef RAD_NORMAL_MAPS
    if (!(dot3(out, l->ng) > 0.0f)) { /* a normal map's cosine drew it into the face */
        *weight = (float3)(0.0f);
        *pdf = -1.0f;
        return out;
    }
#endif
    *pdf = keep * (w.z * (1.0f / RAD_PI));
    *weight = l->colour * (1.0f / keep);
    return out;
}
#endif

/* The reflectance with which the radiosity solution reflects the light at `hit`, whose colour
 * (material_at) is rho there: rho, or under a specular layer (rho its base colour) the diffuse
 * part's share less the dielectric layer's mean albedo, and the lobe's mean albedo
 * (host/scene/material_model.h: radiosityReflectance, at this point's metallic and roughness). */
inline float3 material_solution_reflectance(const SceneData* scene, Hit hit, float3 rho) {
#ifdef RAD_LAYERS
    if (material_layered(scene, hit.face)) {
        const LayerAt at = layer_at(scene, hit, rho);
        const float2 e = layer_average(scene->ggxAlbedo, at.roughness);
        /* each lobe's scale at the mean E1 (ggx_energy_at) */
        return at.diffuse * (1.0f - ggx_energy_at(e.x, e.x, at.dielectricF0, at.dielectricF90) *
                                        (at.dielectricF0 * e.x + (at.dielectricF90 - at.dielectricF0) * e.y)) +
               ggx_energy_at(e.x, e.x, at.f0, at.f90) * (at.f0 * e.x + (at.f90 - at.f0) * e.y);
    }
#endif
    return rho;
}

/* f(wo, wi) cos_i per channel toward the unit direction `toward`, and in *pdf the density with
 * which the surface's own sampling draws it (material_scatter, layered_scatter); both 0 where it
 * points below the surface (for a rough metal: below the shading normal or the face). */
inline float3 lobe_eval(const Lobe* l, float3 toward, float* pdf) {
    *pdf = 0.0f;
#ifdef RAD_LAYERS
    if (l->kind == RAD_LOBE_LAYERED) {
        float3 diffuse, layer;
        float diffusePdf, layerPdf;
        layered_parts(l, toward, &diffuse, &layer, &diffusePdf, &layerPdf);
        *pdf = diffusePdf + layerPdf;
        return diffuse + layer;
    }
#endif
    if (l->kind == RAD_SPECULAR_NONE) {
        const float cosine = dot3(toward, l->n);
        if (!(cosine > 0.0f) || !(dot3(toward, l->ng) > 0.0f)) return (float3)(0.0f);
        *pdf = cosine * (1.0f / RAD_PI);
        return l->colour * (cosine * (1.0f / RAD_PI));
    }
    if (l->behindLights != RAD_BEHIND_NONE && !(dot3(toward, l->ng) > 0.0f)) {
        /* through the pane: the reflection about the microfacet it mirrors (rough_glass_scatter) */
        if (!(dot3(toward, l->ng) < 0.0f)) return (float3)(0.0f);
        const float3 r = (float3)(dot3(toward, l->t), dot3(toward, l->b), -dot3(toward, l->n));
        float cosine;
        const float f = ggx_reflection(l->wo, r, l->alpha, &cosine);
        if (!(f > 0.0f)) return (float3)(0.0f);
        float cost;
        const float passes = 1.0f - dielectric_fresnel(cosine, l->eta, &cost);
        *pdf = ggx_reflection_pdf(l->wo, r, l->alpha) * passes;
        return l->colour * (f * passes);
    }
    if (!(dot3(toward, l->ng) > 0.0f)) return (float3)(0.0f);
    const float3 wi = (float3)(dot3(toward, l->t), dot3(toward, l->b), dot3(toward, l->n));
    float cosine;
    const float f = ggx_reflection(l->wo, wi, l->alpha, &cosine);
    if (!(f > 0.0f)) return (float3)(0.0f);
    *pdf = ggx_reflection_pdf(l->wo, wi, l->alpha);
    if (l->kind == RAD_SPECULAR_GLASS || l->kind == RAD_SPECULAR_THIN_GLASS) {
        float cost;
        float fresnel = dielectric_fresnel(cosine, l->eta, &cost);
        /* rough_glass_scatter reflects with that chance, and always where the direction it would
         * pass on in instead (mirrored through a pane, refracted into a solid) is bent back to
         * this side by the shading normal */
        const float3 h = normalize3(l->wo + wi);
        const float3 w = l->kind == RAD_SPECULAR_THIN_GLASS ? (float3)(wi.x, wi.y, -wi.z)
                                                            : (l->eta * cosine - cost) * h - l->eta * l->wo;
        if (fresnel < 1.0f && !(dot3(w.x * l->t + w.y * l->b + w.z * l->n, l->ng) < 0.0f)) fresnel = 1.0f;
        *pdf *= fresnel;
        return (float3)(f * fresnel);
    }
    return f * l->energy * mirror_fresnel(l->colour, cosine);
}

/* ---- Scattering: the direction a ray goes on in ---- */

/* A direction reflected off a rough metal of GGX alpha `alpha` about normal ns (facing the
 * incoming ray along dir, cosi = -dir . ns > 0), drawn from u by the lobe's visible normals
 * (ggx.h), and in *weight what it carries on per channel: F(wo . m) G2 / G1(wo); 0 where the drawn
 * direction points into the surface (below ns or the face's own normal ng, on dir's side): the
 * light the microfacets shadow, which the surface keeps. */
inline float3 glossy_scatter(float3 f0, float alpha, float3 ns, float3 ng, float3 dir, float cosi, float2 u,
                             float3* weight) {
    float3 t, b;
    frame_about(ns, &t, &b);
    const float3 wo = (float3)(-dot3(dir, t), -dot3(dir, b), cosi);
    const float3 m = ggx_visible_normal(wo, alpha, u);
    const float om = dot3(wo, m);
    const float3 wi = (2.0f * om) * m - wo;
    const float3 out = normalize3(wi.x * t + wi.y * b + wi.z * ns);
    if (!(wi.z > 0.0f) || !(dot3(out, ng) > 0.0f)) {
        *weight = (float3)(0.0f);
        return out;
    }
    *weight = mirror_fresnel(f0, om) * ggx_masking_ratio(wo, wi, alpha);
    return out;
}

/* glossy_scatter's direction off the rough metal face f, its weight times the energy scale
 * (ggx_energy) toward the viewer: where the path goes from a camera (`forward` false) the viewer
 * is where the ray came from (cosine cosi); where it carries light (a shot's ray, `forward`),
 * the direction the light goes on in, so that the radiosity pass and the camera pass scale a
 * metal's light alike (the scale is not reciprocal). */
inline float3 glossy_scatter_scaled(const SceneData* scene, __global const SpecularFace* f, float3 ns, float3 ng,
                                    float3 dir, float cosi, float2 u, bool forward, float3* weight) {
    const float3 f0 = vload3(0, f->colour);
    const float3 out = glossy_scatter(f0, f->colour[3], ns, ng, dir, cosi, u, weight);
    *weight *= glossy_energy(scene, f0, f->colour[3], forward ? fmax(dot3(out, ns), 0.0f) : cosi);
    return out;
}

/* A direction off rough glass (GGX alpha; tint; eta the ratio of indices from the ray's side,
 * `thin` a pane, `entering` whether the ray enters the solid) about normal ns (facing the
 * incoming ray along dir, cosi = -dir . ns > 0; ng the face's normal on that side): a
 * microfacet normal m drawn from u by the lobe's visible normals (ggx.h), then reflection about
 * m with the chance of the Fresnel reflectance at wo . m, else refraction through m (a pane:
 * that reflection mirrored through the surface, glTF's thin-walled transmission, so a smooth
 * pane passes the ray straight on; where the shading normal bends a refracted ray back
 * across the face, it is reflected instead, as at smooth glass); u.xy draws m, u.z the choice.
 * *weight: the
 * reflection's masking ratio G2 / G1(wo) (ggx.h; for a refracted direction, as for the
 * reflection at its angle), times the tint where the light enters the solid or crosses the
 * pane; 0 where the direction falls on the wrong side of the face. *through: it passed. */
inline float3 rough_glass_scatter(float3 tint, float alpha, float eta, bool thin, bool entering, float3 ns, float3 ng,
                                  float3 dir, float cosi, float3 u, float3* weight, bool* through) {
    float3 t, b;
    frame_about(ns, &t, &b);
    const float3 wo = (float3)(-dot3(dir, t), -dot3(dir, b), cosi);
    const float3 m = ggx_visible_normal(wo, alpha, u.xy);
    const float om = dot3(wo, m);
    float cost;
    const float fresnel = dielectric_fresnel(om, eta, &cost);
    const float3 r = (2.0f * om) * m - wo; /* the reflection about m */
    *through = !(u.z < fresnel);
    /* local: the direction it goes on in, and that direction turned above the surface (masking) */
    float3 w, above;
    if (!*through) {
        w = above = r;
    } else if (thin) {
        w = (float3)(r.x, r.y, -r.z);
        above = r;
    } else {
        w = (eta * om - cost) * m - eta * wo;
        above = (float3)(w.x, w.y, -w.z);
    }
    float3 out = normalize3(w.x * t + w.y * b + w.z * ns);
    if (*through && !(dot3(out, ng) < 0.0f)) { /* the shading normal bent it back: reflected, as smooth glass does */
        *through = false;
        w = above = r;
        out = normalize3(r.x * t + r.y * b + r.z * ns);
    }
    const float side = *through ? -1.0f : 1.0f; /* where out must point, along ng */
    if (!(above.z > 0.0f) || !(side * dot3(out, ng) > 0.0f) || !(om > 0.0f) || !(cosi > 1e-7f)) {
        *weight = (float3)(0.0f);
        return out;
    }
    *weight = (*through && (thin || entering) ? tint : (float3)(1.0f)) * ggx_masking_ratio(wo, above, alpha);
    return out;
}

/* A ray along dir hits face `hit.face` (front normal ng) of a kind other than diffuse: returns
 * the direction it goes on in, and sets *weight to what it carries on per channel (a mirror:
 * Schlick's Fresnel; a rough metal: glossy_scatter's, its direction drawn with u.xy; glass: 1 for
 * its reflection, the tint for its transmission (into a solid, or through a thin wall; leaving a
 * solid, 1), the choice drawn with u.x against the Fresnel reflectance; rough glass:
 * rough_glass_scatter's) and *through to whether
 * it passed to the other side. forward: the ray carries light along dir (a shot's), rather than
 * looking for it (glossy_scatter_scaled). */
inline float3 surface_scatter(const SceneData* scene, Hit hit, float3 dir, float3 ng, float3 u, bool forward,
                              float3* weight, bool* through) {
    __global const SpecularFace* f = &scene->geometry.specular[hit.face];
    *through = false;
    if (f->kind == RAD_SPECULAR_RETROREFLECTOR) {
        *weight = vload3(0, f->colour);
        return -dir;
    }
    const bool front = dot3(dir, ng) < 0.0f;
    float cosi;
    const float3 ns = specular_normal(scene, hit, dir, &ng, &cosi);
    if (f->kind == RAD_SPECULAR_GLOSSY) return glossy_scatter_scaled(scene, f, ns, ng, dir, cosi, u.xy, forward, weight);
    float3 reflected = dir + (2.0f * cosi) * ns;
    if (!(dot3(reflected, ng) > 0.0f)) reflected = dir - (2.0f * dot3(dir, ng)) * ng;
    if (f->kind == RAD_SPECULAR_MIRROR) {
        *weight = mirror_fresnel(vload3(0, f->colour), cosi);
        return reflected;
    }
    const float ior = f->colour[3];
    const bool thin = f->kind == RAD_SPECULAR_THIN_GLASS;
    const float eta = thin || front ? 1.0f / ior : ior;
    if (f->alpha > 0.0f)
        return rough_glass_scatter(vload3(0, f->colour), f->alpha, eta, thin, front, ns, ng, dir, cosi, u, weight,
                                   through);
    float cost;
    const float fresnel = dielectric_fresnel(cosi, eta, &cost);
    if (u.x < fresnel) {
        *weight = (float3)(1.0f);
        return reflected;
    }
    *through = true;
    *weight = thin || front ? vload3(0, f->colour) : (float3)(1.0f);
    if (thin) return dir;
    const float3 refracted = normalize3(eta * dir + (eta * cosi - cost) * ns);
    if (!(dot3(refracted, ng) < 0.0f)) { /* the shading normal bent it back: take the face's */
        *through = false;
        *weight = (float3)(1.0f);
        return reflected;
    }
    return refracted;
}

/* The density with which material_scatter drew `dir` off a rough metal (lobe l), which light
 * sampling weighs against; -1 (no weighing) where it is 0. */
inline float lobe_density(const Lobe* l, float3 dir) {
    float pdf;
    lobe_eval(l, dir, &pdf);
    return pdf > 0.0f ? pdf : -1.0f;
}

/* A diffuse surface's direction: cosine-distributed about the lobe's normal, drawn from u; *pdf
 * its density (the cosine's over pi, which cancels the cosine and 1 / pi of the BRDF, so the
 * path's weight is simply multiplied by the reflectance). */
inline float3 diffuse_scatter(const Lobe* l, float2 u, float* pdf) {
    float3 t, b;
    frame_about(l->n, &t, &b);
    const float3 w = cosine_hemisphere(u);
    *pdf = w.z * (1.0f / RAD_PI);
    return w.x * t + w.y * b + w.z * l->n;
}

/* ---- What a surface passes straight on and what it keeps ---- */

/* What a thin pane (material_crossed_by_shadow_rays) passes straight through to a ray along dir
 * that meets it at `hit` (ng: the face's front normal), per channel: the share its Fresnel
 * reflectance lets through times its tint, the mean of what material_scatter's choice passes
 * through. Shadow rays toward punctual lights cross panes so (shadow_ray.h); a rough pane as a
 * smooth one (its blur and its microfacets' masking left out). */
inline float3 material_pane_transmittance(const SceneData* scene, Hit hit, float3 dir, float3 ng) {
    __global const SpecularFace* f = &scene->geometry.specular[hit.face];
    float cosi, cost;
    specular_normal(scene, hit, dir, &ng, &cosi);
    return (1.0f - dielectric_fresnel(cosi, 1.0f / f->colour[3], &cost)) * vload3(0, f->colour);
}

/* The share of the light arriving along dir at a rough metal (F0, alpha; shading normal ns at
 * cosine cosi to -dir, the face's normal ng, both on dir's side) that it reflects (its
 * directional albedo; by reciprocity also what it reflects toward -dir of a uniform sky): the
 * mean of glossy_scatter's weight (0 for directions below either normal) over
 * RAD_GLOSSY_ALBEDO^2 directions, one in each cell of a grid over the square they are drawn
 * from, the grid shifted by a random offset drawn from `key`. An estimate without bias (single
 * scattering loses up to two thirds of the light at roughness 1, and the loss jumps where drawn
 * directions dip below the horizon, which a fixed midpoint rule misses by 2 %:
 * tests/test_kernels.cpp), deterministic for a key. With `scene` (else 0: single scattering),
 * each direction's weight is scaled toward it, as a shot's ray is (glossy_scatter_scaled). */
#define RAD_GLOSSY_ALBEDO 4u
inline float3 glossy_albedo(const SceneData* scene, float3 f0, float alpha, float3 ns, float3 ng, float3 dir,
                           float cosi, uint key) {
    const float2 shift = specular_choice(key, 0u).xy;
    float3 sum = (float3)(0.0f);
    for (uint i = 0u; i < RAD_GLOSSY_ALBEDO; ++i)
        for (uint k = 0u; k < RAD_GLOSSY_ALBEDO; ++k) {
            const float2 u = ((float2)((float)i, (float)k) + shift) / (float)RAD_GLOSSY_ALBEDO;
            float3 w;
            const float3 out = glossy_scatter(f0, alpha, ns, ng, dir, cosi, u, &w);
            if (scene != 0) w *= glossy_energy(scene, f0, alpha, fmax(dot3(out, ns), 0.0f));
            sum += w;
        }
    return sum / (float)(RAD_GLOSSY_ALBEDO * RAD_GLOSSY_ALBEDO);
}

/* What the inside of a solid glass passes on of the light that crossed it to `hit` on one of its
 * faces, met from within (`front` false), per channel: exp(-sigma t) over the ray's length t
 * there (KHR_materials_volume's attenuation, Beer-Lambert); 1 elsewhere. */
inline float3 medium_transmittance(__global const SpecularFace* f, Hit hit, bool front) {
    if (front || f->kind != RAD_SPECULAR_GLASS) return (float3)(1.0f);
    return exp(-vload3(0, f->attenuation) * hit.t);
}

/* surface_scatter, with what the solid's inside passed on to the face the ray met from within
 * (medium_transmittance: the light a solid glass absorbs on the way). dir is a unit vector. */
inline float3 material_scatter(const SceneData* scene, Hit hit, float3 dir, float3 ng, float3 u, bool forward,
                               float3* weight, bool* through) {
    const float3 next = surface_scatter(scene, hit, dir, ng, u, forward, weight, through);
    *weight *= medium_transmittance(&scene->geometry.specular[hit.face], hit, dot3(dir, ng) < 0.0f);
    return next;
}

/* What a face of a kind other than diffuse keeps of the light that reaches it along dir at
 * `hit`, per channel: 1 less the mean of what material_scatter passes on (a mirror's 1 - F; a
 * rough metal's 1 - its albedo; glass's (1 - F) x (1 - tint) where the transmitted light is
 * tinted, rough glass's as smooth glass's: what its microfacets' masking loses is left out;
 * met from within a solid, what its inside absorbed on the way). The light a direct-light kernel finds arriving at a mirror's or glass's element counts
 * as absorbed there only so far (the rest goes on, and other elements' rays find it), as the
 * shots leave only that part there. */
inline float3 material_keeps(const SceneData* scene, Hit hit, float3 dir) {
    __global const SpecularFace* f = &scene->geometry.specular[hit.face];
    if (f->kind == RAD_SPECULAR_RETROREFLECTOR) return 1.0f - vload3(0, f->colour);
    float3 ng = vload3(0, scene->geometry.faces[hit.face].normal);
    const bool front = dot3(dir, ng) < 0.0f;
    float cosi, cost;
    const float3 ns = specular_normal(scene, hit, dir, &ng, &cosi);
    if (f->kind == RAD_SPECULAR_MIRROR) return 1.0f - mirror_fresnel(vload3(0, f->colour), cosi);
    if (f->kind == RAD_SPECULAR_GLOSSY) { /* keyed by face, point and direction: decorrelated, reproducible */
        const uint key = rad_hash2(rad_hash2(rad_hash2((uint)hit.face, as_uint(hit.b1)), as_uint(hit.b2)),
                                   as_uint(dir.x) ^ rad_hash2(as_uint(dir.y), as_uint(dir.z)));
        return fmax(1.0f - glossy_albedo(scene, vload3(0, f->colour), f->colour[3], ns, ng, dir, cosi, key), 0.0f);
    }
    const bool thin = f->kind == RAD_SPECULAR_THIN_GLASS;
    if (!thin && !front) return 1.0f - medium_transmittance(f, hit, front); /* leaving a solid: untinted, absorbed inside */
    const float eta = 1.0f / f->colour[3];
    const float fresnel = dielectric_fresnel(cosi, eta, &cost);
    /* where the shading normal bends the refracted ray back, material_scatter reflects it whole */
    if (!thin && !(dot3(normalize3(eta * dir + (eta * cosi - cost) * ns), ng) < 0.0f)) return (float3)(0.0f);
    return (1.0f - fresnel) * (1.0f - vload3(0, f->colour));
}

#endif
