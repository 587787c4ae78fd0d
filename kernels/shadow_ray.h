/* What of a punctual light's light reaches a point along the straight line to it: all of it
 * where nothing is in the way, none where an opaque face, a mirror or solid glass is (a point
 * light's image in a mirror or through a lens is no straight line: rays from the lights bring
 * that light, host/solver/punctual_caustics.h), and
 * through thin panes (glTF's thin-walled glass, RAD_SPECULAR_THIN_GLASS) what each passes
 * straight on: its (1 - Fresnel reflectance) x tint at the angle the line crosses it
 * (material.h: material_pane_transmittance). A window so lets the sun in, in every pass: the elements'
 * direct light, the camera pass and the path tracer, which no other path could bring it by. */
#ifndef RADIOSITY_SHADOW_RAY_H
#define RADIOSITY_SHADOW_RAY_H

#include "bvh_traverse.h"
#include "material.h"
#include "specular_walk.h"

/* Per channel, what reaches p from `distance` along the unit direction dir (0: a directional
 * light, infinitely far). lift: the least distance a ray leaves a pane it crosses by. */
inline float3 shadow_transmittance(const SceneData* scene, float3 p, float3 dir, float distance, float lift) {
    const float3 start = p;
    float3 through = (float3)(1.0f);
    float left = distance > 0.0f ? distance : INFINITY;
    /* One traversal call in the loop, so that it is inlined once. */
    for (uint crossed = 0u;; ++crossed) {
        const Hit hit = trace_within(&scene->geometry, p, dir, left);
        if (hit.face < 0) return through;
#ifdef RAD_SPECULAR_TRANSPORT
        if (!material_crossed_by_shadow_rays(material_kind(scene, hit.face)) || crossed == RAD_SPECULAR_BOUNCES)
            return (float3)(0.0f);
        const float3 ng = vload3(0, scene->geometry.faces[hit.face].normal);
        through *= material_pane_transmittance(scene, hit, dir, ng);
        if (!(fmax(fmax(through.x, through.y), through.z) > 0.0f)) return (float3)(0.0f);
        p = leave_surface(p, hit, dir, ng, dot3(dir, ng) < 0.0f, true, lift);
        if (distance > 0.0f) {
            left = distance - dot3(p - start, dir);
            if (!(left > 0.0f)) return through;
        }
#else
        return (float3)(0.0f);
#endif
    }
}

#endif
