/* The direct light of many punctual lights at a point without a shadow ray per light: a
 * light cut (Walter et al., "Lightcuts", SIGGRAPH 2005). The lights' tree (LightNode) is cut
 * into clusters, each lit by its representative: the cluster's summed intensity times the
 * representative's geometry (spot attenuation x cos / r^2) and what of it reaches the point
 * (shadow_ray.h), one shadow ray. The
 * cut starts at the root and splits the cluster with the largest error bound (at most its
 * unoccluded contribution's upper bound: summed luminance x max cos / min r^2 over its box)
 * until every bound is below RAD_LIGHT_CUT_ERROR of the total, or the cut holds
 * RAD_LIGHT_CUT_SIZE clusters. A child keeps its parent's representative where it holds it, and
 * reuses its shadow ray. Deterministic: the same points, lights and scene give the same cut.
 * Up to RAD_EXACT_LIGHTS lights, every light gets its own shadow ray instead (exact). */
#ifndef RADIOSITY_LIGHT_TREE_H
#define RADIOSITY_LIGHT_TREE_H

#include "bvh_traverse.h"
#include "punctual_light.h"
#include "shadow_ray.h"

#define RAD_EXACT_LIGHTS 16u
#define RAD_LIGHT_CUT_ERROR 0.01f
#define RAD_LIGHT_CUT_SIZE 48

/* Where the lit point lies on a mirror or glass face (receiver.face >= 0, at barycentric weights
 * receiver.b1, b2), the share of the light arriving along -toLight that it keeps
 * (material_keeps); 1 elsewhere (receiver.face -1). */
inline float3 receiver_keeps(const SceneData* scene, Hit receiver, float3 toLight) {
#ifdef RAD_SPECULAR_TRANSPORT
    if (receiver.face >= 0) return material_keeps(scene, receiver, -toLight);
#endif
    return (float3)(1.0f);
}

/* The receiver of points that lie on no mirror or glass face. */
inline Hit diffuse_receiver(void) {
    Hit none;
    none.t = 0.0f;
    none.face = -1;
    none.b1 = 0.0f;
    none.b2 = 0.0f;
    return none;
}

/* The irradiance the light sends to p (normal n) per unit of its intensity, per channel, through
 * one shadow ray: its geometry times what reaches p (shadow_ray.h), times what the receiver
 * keeps. lift: as shadow_transmittance takes it. */
inline float3 unit_light_at(const SceneData* scene, __global const PunctualLight* light, float3 p, float3 n,
                            Hit receiver, float lift, uint* rays) {
    float3 toLight;
    float distance;
    const float3 e = punctual_irradiance(light, p, n, &toLight, &distance);
    const float lum = light->intensity[3];
    if (!(lum > 0.0f) || !(fmax(fmax(e.x, e.y), e.z) > 0.0f)) return (float3)(0.0f);
    ++*rays;
    const float3 reaching = shadow_transmittance(scene, p, toLight, distance, lift);
    if (!(fmax(fmax(reaching.x, reaching.y), reaching.z) > 0.0f)) return (float3)(0.0f);
    /* e = geometry x intensity: the geometry from the luminance channels. */
    const float geometry = ((0.2126f * e.x + 0.7152f * e.y) + 0.0722f * e.z) / lum;
    return geometry * reaching * receiver_keeps(scene, receiver, toLight);
}

/* An upper bound on the luminance irradiance a cluster can send to p (normal n). */
inline float cluster_bound(__global const LightNode* c, float3 p, float3 n) {
    const float3 lo = vload3(0, c->lo), hi = vload3(0, c->hi);
    const float3 q = clamp(p, lo, hi) - p;
    const float d2 = dot3(q, q);
    /* The largest n . (x - p) over the box: if none is positive, all its lights are behind. */
    const float front = (fmax(n.x * (lo.x - p.x), n.x * (hi.x - p.x)) + fmax(n.y * (lo.y - p.y), n.y * (hi.y - p.y))) +
                        fmax(n.z * (lo.z - p.z), n.z * (hi.z - p.z));
    if (!(front > 0.0f)) return 0.0f;
    if (!(d2 > 0.0f)) return INFINITY;
    return c->lo[3] * fmin(1.0f, front / sqrt(d2)) / d2;
}

inline float luminance3(float3 c) {
    return (0.2126f * c.x + 0.7152f * c.y) + 0.0722f * c.z;
}

/* Irradiance at p (normal n) from every one of the scene's punctual lights: the directional ones
 * first (each exact), then the point and spot lights, which their tree (rooted at 0) covers when
 * there are more than RAD_EXACT_LIGHTS of them. receiver: where p lies when on a mirror or glass
 * face, else diffuse_receiver() (receiver_keeps); lift: the least distance a shadow ray leaves a
 * thin pane it crosses by. *rays counts the shadow rays traced. */
inline float3 punctual_lights_at(const SceneData* scene, float3 p, float3 n, Hit receiver, float lift, uint* rays) {
    __global const PunctualLight* lights = scene->punctualLights;
    __global const LightNode* tree = scene->lightTree;
    const uint lightCount = scene->about.punctualCount, directional = scene->about.directional;
    float3 total = (float3)(0.0f);
    const uint others = lightCount - directional; /* point and spot lights */
    for (uint k = 0u; k < (others > RAD_EXACT_LIGHTS ? directional : lightCount); ++k) {
        float3 toLight;
        float distance;
        const float3 e = punctual_irradiance(&lights[k], p, n, &toLight, &distance);
        if (!(fmax(fmax(e.x, e.y), e.z) > 0.0f)) continue;
        ++*rays;
        const float3 reaching = shadow_transmittance(scene, p, toLight, distance, lift);
        if (fmax(fmax(reaching.x, reaching.y), reaching.z) > 0.0f)
            total += e * reaching * receiver_keeps(scene, receiver, toLight);
    }
    if (others <= RAD_EXACT_LIGHTS) return total;

    int node[RAD_LIGHT_CUT_SIZE];
    float error[RAD_LIGHT_CUT_SIZE];
    float3 unit[RAD_LIGHT_CUT_SIZE], estimate[RAD_LIGHT_CUT_SIZE];
    int size = 0;
    /* Clusters waiting to join the cut (the root; then a split cluster's two children), each
     * with its representative's unit irradiance where a parent already traced it (known). One
     * place traces the representatives' shadow rays, so the traversal is inlined once here. */
    int pendingNode[2] = {0, 0};
    float3 pendingUnit[2] = {(float3)(0.0f), (float3)(0.0f)};
    bool known[2] = {false, false};
    int pending = 1;
    for (;;) {
        for (int q = 0; q < pending; ++q) {
            __global const LightNode* cn = &tree[pendingNode[q]];
            const float3 gu = known[q] ? pendingUnit[q]
                                       : unit_light_at(scene, &lights[directional + cn->rep], p, n, receiver, lift, rays);
            const float3 est = gu * vload3(0, cn->intensity);
            node[size] = pendingNode[q];
            unit[size] = gu;
            estimate[size] = est;
            error[size] = cn->left < 0 ? 0.0f : fmax(cluster_bound(cn, p, n), luminance3(est));
            total += est;
            ++size;
        }
        if (size >= RAD_LIGHT_CUT_SIZE) break;
        int worst = 0;
        for (int k = 1; k < size; ++k)
            if (error[k] > error[worst]) worst = k;
        if (!(error[worst] > RAD_LIGHT_CUT_ERROR * luminance3(total))) break;
        /* Split it: remove it (the last entry takes its place) and queue its children, which
         * keep its shadow ray where they keep its representative. */
        __global const LightNode* parent = &tree[node[worst]];
        const float3 parentUnit = unit[worst];
        total -= estimate[worst];
        --size;
        node[worst] = node[size];
        unit[worst] = unit[size];
        estimate[worst] = estimate[size];
        error[worst] = error[size];
        pendingNode[0] = parent->left;
        pendingNode[1] = parent->right;
        known[0] = tree[parent->left].rep == parent->rep;
        known[1] = tree[parent->right].rep == parent->rep;
        pendingUnit[0] = parentUnit;
        pendingUnit[1] = parentUnit;
        pending = 2;
    }
    return fmax(total, (float3)(0.0f));
}

#endif
