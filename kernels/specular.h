/* Ideal specular surfaces (SpecularFace, shared_types.h; host/scene/material_model.h says which
 * materials are): where the path tracer, the camera pass and the progressive solve's shots
 * follow light by reflection and refraction instead of reflecting it diffusely, and what
 * punctual lights' shadow rays pass through (thin panes: shadow_ray.h) and direct light leaves
 * at them (specular_keeps). The face's shading normal (interpolated from
 * its corners', so a sphere of flat faces reflects as a sphere) decides the directions; where it
 * would send a ray to the wrong side of the surface, the face's own normal does. */
#ifndef RADIOSITY_SPECULAR_H
#define RADIOSITY_SPECULAR_H

#include "bvh_traverse.h"
#include "vector_math.h"

/* The most mirrors and glass surfaces the camera pass follows in a row before the sample is
 * dropped (the shots follow more: RAD_SHOT_SPECULAR_BOUNCES in shoot.cl). */
#define RAD_SPECULAR_BOUNCES 8u

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

/* A ray along dir hits specular face `f` (front normal ng) at `hit`: returns the direction it
 * goes on in, and sets *weight to what it carries on per channel (a mirror: Schlick's Fresnel;
 * glass: 1 for its reflection, the tint for its transmission (into a solid, or through a thin
 * wall; leaving a solid, 1), the choice drawn with u against
 * the Fresnel reflectance) and *through to whether it passed to the other side. */
inline float3 specular_scatter(__global const SpecularFace* f, Hit hit, float3 dir, float3 ng, float u,
                               float3* weight, bool* through) {
    const bool front = dot3(dir, ng) < 0.0f;
    float cosi;
    const float3 ns = specular_normal(f, hit, dir, &ng, &cosi);
    float3 reflected = dir + (2.0f * cosi) * ns;
    if (!(dot3(reflected, ng) > 0.0f)) reflected = dir - (2.0f * dot3(dir, ng)) * ng;
    *through = false;
    if (f->kind == RAD_SPECULAR_MIRROR) {
        *weight = mirror_fresnel(vload3(0, f->colour), cosi);
        return reflected;
    }
    const float ior = f->colour[3];
    const bool thin = f->kind == RAD_SPECULAR_THIN_GLASS;
    const float eta = thin || front ? 1.0f / ior : ior;
    float cost;
    const float fresnel = dielectric_fresnel(cosi, eta, &cost);
    if (u < fresnel) {
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

/* What a mirror or glass face keeps of the light that reaches it along dir at `hit`, per channel:
 * 1 less the mean of what specular_scatter passes on (a mirror's 1 - F; glass's (1 - F) x
 * (1 - tint) where the transmitted light is tinted). The light a direct-light kernel finds
 * arriving at a mirror's or glass's element counts as absorbed there only so far (the rest goes
 * on, and other elements' rays find it), as the shots leave only that part there. */
inline float3 specular_keeps(__global const SpecularFace* f, Hit hit, float3 dir, float3 ng) {
    const bool front = dot3(dir, ng) < 0.0f;
    float cosi, cost;
    const float3 ns = specular_normal(f, hit, dir, &ng, &cosi);
    if (f->kind == RAD_SPECULAR_MIRROR) return 1.0f - mirror_fresnel(vload3(0, f->colour), cosi);
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

/* Whether a ray ends, black, at the mirror or glass face it hit: a mirror met on a side
 * without patches (`patched`: the side has patches), as any face's black back. Glass passes
 * light on from either side. */
inline bool specular_black(__global const SpecularFace* surface, bool patched) {
    return surface->kind == RAD_SPECULAR_MIRROR && !patched;
}

/* A ray from *org along dir that hit the mirror or glass face `surface` at `hit` (ng: the face's
 * front normal, `front`: whether the ray met the front) goes on: returns the direction it goes
 * on in, moves *org off the surface to the side it leaves to, and sets *carried to what the
 * surface passes on per channel (the choice at glass drawn with u). */
inline float3 specular_continue(__global const SpecularFace* surface, Hit hit, float3 dir, float3 ng, bool front,
                                float u, float lift, float3* org, float3* carried) {
    bool through;
    const float3 next = specular_scatter(surface, hit, dir, ng, u, carried, &through);
    *org = leave_specular(*org, hit, dir, ng, front, through, lift);
    return next;
}

#endif
