/* Mirrors, rough metals and glass (SpecularFace, shared_types.h; host/scene/material_model.h says
 * which materials are): where the path tracer, the camera pass and the progressive solve's shots
 * follow light by reflection (about the mirror direction, or drawn from a rough metal's GGX lobe:
 * ggx.h) and refraction instead of reflecting it diffusely, and what
 * punctual lights' shadow rays pass through (thin panes: shadow_ray.h) and direct light leaves
 * at them (specular_keeps). The face's shading normal (interpolated from
 * its corners', so a sphere of flat faces reflects as a sphere) decides the directions; where it
 * would send a ray to the wrong side of the surface, the face's own normal does. */
#ifndef RADIOSITY_SPECULAR_H
#define RADIOSITY_SPECULAR_H

#include "bvh_traverse.h"
#include "ggx.h"
#include "rng.h"
#include "vector_math.h"

/* The most mirrors and glass surfaces the camera pass follows in a row before the sample is
 * dropped (the shots follow more: RAD_SHOT_SPECULAR_BOUNCES in shoot.cl). */
#define RAD_SPECULAR_BOUNCES 8u

/* Whether a specular kind only reflects (a mirror or a rough metal): its back is black where it
 * has no patches, as any opaque face's. */
inline bool specular_reflects_only(uint kind) {
    return kind != RAD_SPECULAR_NONE && kind < RAD_SPECULAR_GLASS;
}

/* The two uniform numbers a ray's `bounce`-th scattering draws from (specular_scatter), from a
 * per-ray key: the first picks glass's reflection or transmission, both a rough metal's
 * microfacet normal. */
inline float2 specular_choice(uint key, uint bounce) {
    return (float2)(unit_float(rad_hash2(key, bounce)), unit_float(rad_hash2(key ^ 0x68e31da4u, bounce)));
}

/* What face `face` is: RAD_SPECULAR_NONE unless the scene has mirrors or glass (built with
 * -DRAD_SPECULAR_TRANSPORT: host/prepared/device_scene.h). */
inline uint specular_kind(const SceneData* scene, int face) {
#ifdef RAD_SPECULAR_TRANSPORT
    return scene->specular[face].kind;
#else
    return RAD_SPECULAR_NONE;
#endif
}

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

/* A rough metal's lobe where a ray along dir hit it: the frame about the shading normal (ns, t,
 * b), the face's normal ng toward the ray's side, wo (toward where the ray came from) in that
 * frame, F0 and alpha. What light sampling at the metal evaluates (glossy_lights.h). */
typedef struct {
    float3 ns, ng, t, b, wo, f0;
    float alpha;
} GlossyLobe;

inline GlossyLobe glossy_lobe(__global const SpecularFace* f, Hit hit, float3 dir, float3 ng) {
    GlossyLobe l;
    float cosi;
    l.ng = ng;
    l.ns = specular_normal(f, hit, dir, &l.ng, &cosi);
    frame_about(l.ns, &l.t, &l.b);
    l.wo = (float3)(-dot3(dir, l.t), -dot3(dir, l.b), cosi);
    l.f0 = vload3(0, f->colour);
    l.alpha = f->colour[3];
    return l;
}

/* f(wo, wi) cos_i per channel toward the unit direction `toward`, and in *pdf the density with
 * which glossy_scatter draws it; both 0 where it points below the shading normal or the face. */
inline float3 glossy_eval(const GlossyLobe* l, float3 toward, float* pdf) {
    *pdf = 0.0f;
    if (!(dot3(toward, l->ng) > 0.0f)) return (float3)(0.0f);
    const float3 wi = (float3)(dot3(toward, l->t), dot3(toward, l->b), dot3(toward, l->ns));
    float cosine;
    const float f = ggx_reflection(l->wo, wi, l->alpha, &cosine);
    if (!(f > 0.0f)) return (float3)(0.0f);
    *pdf = ggx_reflection_pdf(l->wo, wi, l->alpha);
    return f * mirror_fresnel(l->f0, cosine);
}

/* A ray along dir hits specular face `f` (front normal ng) at `hit`: returns the direction it
 * goes on in, and sets *weight to what it carries on per channel (a mirror: Schlick's Fresnel;
 * a rough metal: glossy_scatter's, its direction drawn with u; glass: 1 for its reflection, the
 * tint for its transmission (into a solid, or through a thin wall; leaving a solid, 1), the
 * choice drawn with u.x against the Fresnel reflectance) and *through to whether it passed to
 * the other side. */
inline float3 specular_scatter(__global const SpecularFace* f, Hit hit, float3 dir, float3 ng, float2 u,
                               float3* weight, bool* through) {
    const bool front = dot3(dir, ng) < 0.0f;
    float cosi;
    const float3 ns = specular_normal(f, hit, dir, &ng, &cosi);
    *through = false;
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

/* What a thin pane (RAD_SPECULAR_THIN_GLASS) passes straight through to a ray along dir that
 * meets it at `hit` (ng: the face's front normal), per channel: the share its Fresnel reflectance
 * lets through times its tint, the mean of what specular_scatter's choice passes through. Shadow
 * rays toward punctual lights cross panes so (shadow_ray.h). */
inline float3 pane_transmittance(__global const SpecularFace* f, Hit hit, float3 dir, float3 ng) {
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

/* What a mirror, rough metal or glass face keeps of the light that reaches it along dir at `hit`,
 * per channel: 1 less the mean of what specular_scatter passes on (a mirror's 1 - F; a rough
 * metal's 1 - its albedo; glass's (1 - F) x (1 - tint) where the transmitted light is tinted).
 * The light a direct-light kernel finds
 * arriving at a mirror's or glass's element counts as absorbed there only so far (the rest goes
 * on, and other elements' rays find it), as the shots leave only that part there. */
inline float3 specular_keeps(__global const SpecularFace* f, Hit hit, float3 dir, float3 ng) {
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
    /* where the shading normal bends the refracted ray back, specular_scatter reflects it whole */
    if (!thin && !(dot3(normalize3(eta * dir + (eta * cosi - cost) * ns), ng) < 0.0f)) return (float3)(0.0f);
    return (1.0f - fresnel) * (1.0f - vload3(0, f->colour));
}

/* Where a ray from `org` that met a specular surface (front normal ng, met from the front
 * when `front`) goes on from: off the surface, on the side it leaves to (the other one when it
 * passed `through`), by more than the hit point's rounding (32 ulps of the larger coordinate)
 * and at least `lift`, so the new ray cannot find the face it leaves. */
inline float3 leave_specular(float3 org, Hit hit, float3 dir, float3 ng, bool front, bool through, float lift) {
    const float3 p = org + hit.t * dir;
    const float off = fmax(lift, fmax(max_abs3(org), max_abs3(p)) * 0x1p-18f);
    return p + ((front != through) ? off : -off) * ng;
}

/* Whether a ray ends, black, at the specular face it hit: a mirror or rough metal met on a side
 * without patches (`patched`: the side has patches), as any face's black back. Glass passes
 * light on from either side. */
inline bool specular_black(__global const SpecularFace* surface, bool patched) {
    return specular_reflects_only(surface->kind) && !patched;
}

/* A ray from *org along dir that hit the mirror or glass face `surface` at `hit` (ng: the face's
 * front normal, `front`: whether the ray met the front) goes on: returns the direction it goes
 * on in, moves *org off the surface to the side it leaves to, and sets *carried to what the
 * surface passes on per channel (the choice at glass, the direction off a rough metal, drawn with
 * u). */
inline float3 specular_continue(__global const SpecularFace* surface, Hit hit, float3 dir, float3 ng, bool front,
                                float2 u, float lift, float3* org, float3* carried) {
    bool through;
    const float3 next = specular_scatter(surface, hit, dir, ng, u, carried, &through);
    *org = leave_specular(*org, hit, dir, ng, front, through, lift);
    return next;
}

#endif
