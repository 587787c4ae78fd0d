/* Ideal specular surfaces (SpecularFace, shared_types.h; host/scene/material_model.h says which
 * materials are): where the path tracer, the camera pass and the progressive solve's shots
 * follow light by reflection and refraction instead of reflecting it diffusely. The face's shading normal (interpolated from
 * its corners', so a sphere of flat faces reflects as a sphere) decides the directions; where it
 * would send a ray to the wrong side of the surface, the face's own normal does. */
#ifndef RADIOSITY_SPECULAR_H
#define RADIOSITY_SPECULAR_H

#include "bvh_traverse.h"
#include "vector_math.h"

/* The most mirrors and glass surfaces the camera pass follows in a row before the sample is
 * dropped (the shots follow more: RAD_SHOT_SPECULAR_BOUNCES in shoot.cl). */
#define RAD_SPECULAR_BOUNCES 8u

inline uint specular_kind(__global const SpecularFace* faces, uint present, int face) {
    return present ? faces[face].kind : RAD_SPECULAR_NONE;
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

/* A ray along dir hits specular face `f` (front normal ng) at `hit`: returns the direction it
 * goes on in, and sets *weight to what it carries on per channel (a mirror: Schlick's Fresnel;
 * glass: 1 for its reflection, the tint for its transmission (into a solid, or through a thin
 * wall; leaving a solid, 1), the choice drawn with u against
 * the Fresnel reflectance) and *through to whether it passed to the other side. */
inline float3 specular_scatter(__global const SpecularFace* f, Hit hit, float3 dir, float3 ng, float u,
                               float3* weight, bool* through) {
    const bool front = dot3(dir, ng) < 0.0f;
    const float b0 = 1.0f - hit.b1 - hit.b2;
    float3 ns = b0 * vload3(0, f->normals[0]) + hit.b1 * vload3(0, f->normals[1]) + hit.b2 * vload3(0, f->normals[2]);
    ns = normalize3(ns);
    if (!front) { /* both toward the side the ray comes from */
        ng = -ng;
        ns = -ns;
    }
    float cosi = -dot3(dir, ns);
    if (!(cosi > 0.0f) || !(dot3(ns, ng) > 0.0f)) {
        ns = ng;
        cosi = -dot3(dir, ng);
    }
    float3 reflected = dir + (2.0f * cosi) * ns;
    if (!(dot3(reflected, ng) > 0.0f)) reflected = dir - (2.0f * dot3(dir, ng)) * ng;
    *through = false;
    if (f->kind == RAD_SPECULAR_MIRROR) {
        const float3 f0 = vload3(0, f->colour);
        const float m = 1.0f - cosi, m2 = m * m;
        *weight = f0 + (1.0f - f0) * (m2 * m2 * m);
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
