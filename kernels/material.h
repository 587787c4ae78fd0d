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
 *   rough metal  glTF's GGX microfacet reflection (ggx.h), alpha = roughness^2, the same Fresnel;
 *   glass        the dielectric Fresnel from its IOR picks reflection or transmission; the
 *                transmitted light is tinted by colour (as it enters a solid, at every crossing of
 *                a thin pane), refracted by a solid, straight through a thin pane;
 *   retroreflector  light goes back the way it came, times colour (a kind for tests: no glTF
 *                material maps to it).
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
 * values, or where the face has a texture, the material's factors times the texture there. */
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
    if (ft->emissiveSlot >= 0) {
        const float2 uv = b0 * vload2(0, ft->emissiveUv) + hit.b1 * vload2(1, ft->emissiveUv) +
                          hit.b2 * vload2(2, ft->emissiveUv);
        *le = vload3(0, ft->emission) *
              sample_texture(scene->geometry.texels, scene->srgb, &scene->geometry.textureSlots[ft->emissiveSlot], uv);
    }
}

/* The two uniform numbers a ray's `bounce`-th scattering draws from, from a per-ray key: the
 * first picks glass's reflection or transmission, both a rough metal's microfacet normal. */
inline float2 specular_choice(uint key, uint bounce) {
    return (float2)(unit_float(rad_hash2(key, bounce)), unit_float(rad_hash2(key ^ 0x68e31da4u, bounce)));
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

/* The normal that reflects and refracts a ray along dir at the hit on face f (front normal *ng):
 * the shading normal, or the face's own where the shading normal would send the ray to the wrong
 * side; both turned toward the side the ray comes from (*ng too). *cosi: its cosine with -dir. */
inline float3 specular_normal(__global const SpecularFace* f, Hit hit, float3 dir, float3* ng, float* cosi) {
    const float b0 = 1.0f - hit.b1 - hit.b2;
    float3 ns = b0 * vload3(0, f->normals[0]) + hit.b1 * vload3(0, f->normals[1]) + hit.b2 * vload3(0, f->normals[2]);
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

/* ---- Lobes: what light sampling evaluates (diffuse surfaces, rough metals) ---- */

/* A surface's lobe where a ray along dir met it: a diffuse one (reflectance `colour` about n) or
 * a rough metal's (F0 `colour`, GGX alpha, about the shading normal n, with the frame (t, b, n),
 * the face's normal ng toward the ray's side and wo, toward where the ray came from, in that
 * frame). */
typedef struct {
    uint kind;
    float3 n, ng, t, b, wo, colour;
    float alpha;
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
    l.alpha = 1.0f;
    return l;
}

/* A rough metal's lobe (face f) where a ray along dir hit it; ng: the face's front normal. */
inline Lobe glossy_lobe(__global const SpecularFace* f, Hit hit, float3 dir, float3 ng) {
    Lobe l;
    float cosi;
    l.kind = RAD_SPECULAR_GLOSSY;
    l.ng = ng;
    l.n = specular_normal(f, hit, dir, &l.ng, &cosi);
    frame_about(l.n, &l.t, &l.b);
    l.wo = (float3)(-dot3(dir, l.t), -dot3(dir, l.b), cosi);
    l.colour = vload3(0, f->colour);
    l.alpha = f->colour[3];
    return l;
}

/* f(wo, wi) cos_i per channel toward the unit direction `toward`, and in *pdf the density with
 * which the surface's own sampling draws it (material_scatter); both 0 where it points below the
 * surface (for a rough metal: below the shading normal or the face). */
inline float3 lobe_eval(const Lobe* l, float3 toward, float* pdf) {
    *pdf = 0.0f;
    if (l->kind == RAD_SPECULAR_NONE) {
        const float cosine = dot3(toward, l->n);
        if (!(cosine > 0.0f)) return (float3)(0.0f);
        *pdf = cosine * (1.0f / RAD_PI);
        return l->colour * (cosine * (1.0f / RAD_PI));
    }
    if (!(dot3(toward, l->ng) > 0.0f)) return (float3)(0.0f);
    const float3 wi = (float3)(dot3(toward, l->t), dot3(toward, l->b), dot3(toward, l->n));
    float cosine;
    const float f = ggx_reflection(l->wo, wi, l->alpha, &cosine);
    if (!(f > 0.0f)) return (float3)(0.0f);
    *pdf = ggx_reflection_pdf(l->wo, wi, l->alpha);
    return f * mirror_fresnel(l->colour, cosine);
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

/* A ray along dir hits face `hit.face` (front normal ng) of a kind other than diffuse: returns
 * the direction it goes on in, and sets *weight to what it carries on per channel (a mirror:
 * Schlick's Fresnel; a rough metal: glossy_scatter's, its direction drawn with u; glass: 1 for
 * its reflection, the tint for its transmission (into a solid, or through a thin wall; leaving a
 * solid, 1), the choice drawn with u.x against the Fresnel reflectance) and *through to whether
 * it passed to the other side. */
inline float3 material_scatter(const SceneData* scene, Hit hit, float3 dir, float3 ng, float2 u, float3* weight,
                               bool* through) {
    __global const SpecularFace* f = &scene->geometry.specular[hit.face];
    *through = false;
    if (f->kind == RAD_SPECULAR_RETROREFLECTOR) {
        *weight = vload3(0, f->colour);
        return -dir;
    }
    const bool front = dot3(dir, ng) < 0.0f;
    float cosi;
    const float3 ns = specular_normal(f, hit, dir, &ng, &cosi);
    if (f->kind == RAD_SPECULAR_GLOSSY)
        return glossy_scatter(vload3(0, f->colour), f->colour[3], ns, ng, dir, cosi, u, weight);
    float3 reflected = dir + (2.0f * cosi) * ns;
    if (!(dot3(reflected, ng) > 0.0f)) reflected = dir - (2.0f * dot3(dir, ng)) * ng;
    if (f->kind == RAD_SPECULAR_MIRROR) {
        *weight = mirror_fresnel(vload3(0, f->colour), cosi);
        return reflected;
    }
    const float ior = f->colour[3];
    const bool thin = f->kind == RAD_SPECULAR_THIN_GLASS;
    const float eta = thin || front ? 1.0f / ior : ior;
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
 * through. Shadow rays toward punctual lights cross panes so (shadow_ray.h). */
inline float3 material_pane_transmittance(const SceneData* scene, Hit hit, float3 dir, float3 ng) {
    __global const SpecularFace* f = &scene->geometry.specular[hit.face];
    float cosi, cost;
    specular_normal(f, hit, dir, &ng, &cosi);
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
 * tests/test_kernels.cpp), deterministic for a key. */
#define RAD_GLOSSY_ALBEDO 4u
inline float3 glossy_albedo(float3 f0, float alpha, float3 ns, float3 ng, float3 dir, float cosi, uint key) {
    const float2 shift = specular_choice(key, 0u);
    float3 sum = (float3)(0.0f);
    for (uint i = 0u; i < RAD_GLOSSY_ALBEDO; ++i)
        for (uint k = 0u; k < RAD_GLOSSY_ALBEDO; ++k) {
            const float2 u = ((float2)((float)i, (float)k) + shift) / (float)RAD_GLOSSY_ALBEDO;
            float3 w;
            glossy_scatter(f0, alpha, ns, ng, dir, cosi, u, &w);
            sum += w;
        }
    return sum / (float)(RAD_GLOSSY_ALBEDO * RAD_GLOSSY_ALBEDO);
}

/* What a face of a kind other than diffuse keeps of the light that reaches it along dir at
 * `hit`, per channel: 1 less the mean of what material_scatter passes on (a mirror's 1 - F; a
 * rough metal's 1 - its albedo; glass's (1 - F) x (1 - tint) where the transmitted light is
 * tinted). The light a direct-light kernel finds arriving at a mirror's or glass's element counts
 * as absorbed there only so far (the rest goes on, and other elements' rays find it), as the
 * shots leave only that part there. */
inline float3 material_keeps(const SceneData* scene, Hit hit, float3 dir) {
    __global const SpecularFace* f = &scene->geometry.specular[hit.face];
    if (f->kind == RAD_SPECULAR_RETROREFLECTOR) return 1.0f - vload3(0, f->colour);
    float3 ng = vload3(0, scene->geometry.faces[hit.face].normal);
    const bool front = dot3(dir, ng) < 0.0f;
    float cosi, cost;
    const float3 ns = specular_normal(f, hit, dir, &ng, &cosi);
    if (f->kind == RAD_SPECULAR_MIRROR) return 1.0f - mirror_fresnel(vload3(0, f->colour), cosi);
    if (f->kind == RAD_SPECULAR_GLOSSY) { /* keyed by face, point and direction: decorrelated, reproducible */
        const uint key = rad_hash2(rad_hash2(rad_hash2((uint)hit.face, as_uint(hit.b1)), as_uint(hit.b2)),
                                   as_uint(dir.x) ^ rad_hash2(as_uint(dir.y), as_uint(dir.z)));
        return 1.0f - glossy_albedo(vload3(0, f->colour), f->colour[3], ns, ng, dir, cosi, key);
    }
    const bool thin = f->kind == RAD_SPECULAR_THIN_GLASS;
    if (!thin && !front) return (float3)(0.0f); /* leaving a solid: untinted */
    const float eta = 1.0f / f->colour[3];
    const float fresnel = dielectric_fresnel(cosi, eta, &cost);
    /* where the shading normal bends the refracted ray back, material_scatter reflects it whole */
    if (!thin && !(dot3(normalize3(eta * dir + (eta * cosi - cost) * ns), ng) < 0.0f)) return (float3)(0.0f);
    return (1.0f - fresnel) * (1.0f - vload3(0, f->colour));
}

#endif
