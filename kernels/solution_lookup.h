/* Reading the radiosity solution where a ray lands: the element under the hit (the face's patch
 * by patch_lookup.h, then down the patch's quadtree by element_lookup.h), whose own value a
 * gather ray reads, and the hit's weights on the element's corners, to interpolate values given
 * per vertex (host/mesh/vertices.h: continuous within a surface, never blended across surfaces
 * or creases) where the camera sees them. The camera pass's every mode reads the solution
 * through these. */
#ifndef RADIOSITY_SOLUTION_LOOKUP_H
#define RADIOSITY_SOLUTION_LOOKUP_H

#include "scene_data.h"
#include "bvh_traverse.h"
#include "patch_lookup.h"
#include "element_lookup.h"

typedef struct {
    uint4 corners;  /* the element's vertices */
    float3 weights; /* the hit's weights on them */
} ElementPoint;

/* The element of the side whose first patch is `first` (front: the face's front side) under hit;
 * *weights: the hit's weights on its corners. */
inline uint element_under(const SceneGeometry* scene, __global const ElementNode* elements, Hit hit, uint first,
                          bool front, float3* weights) {
    const GridPoint g = grid_locate(scene->faces[hit.face].subdivision, hit.b1, hit.b2);
    *weights = front ? g.weights : g.weights.xzy; /* a back patch lists its corners 0, 2, 1 */
    return locate_element(elements, first + g.index, weights);
}

/* The same element's vertices, with the weights to interpolate them by. */
inline ElementPoint element_point(const SceneGeometry* scene, __global const ElementNode* elements,
                                  __global const uint4* corners, Hit hit, uint first, bool front) {
    ElementPoint p;
    p.corners = corners[element_under(scene, elements, hit, first, front, &p.weights)];
    return p;
}

inline float3 interpolate_vertices(__global const float4* values, ElementPoint p) {
    return p.weights.x * values[p.corners.x].xyz + p.weights.y * values[p.corners.y].xyz +
           p.weights.z * values[p.corners.z].xyz;
}

#endif
