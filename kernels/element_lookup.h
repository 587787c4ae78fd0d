/* From a point on a patch to the element it lies in: the patch's quadtree (shared_types.h,
 * host/mesh/elements.h) is descended by the point's weights on the current triangle's corners.
 * A weight of at least 1/2 puts the point in that corner's child; otherwise it is in the
 * centre child. The weights are carried down, and end as the point's weights on the element's
 * own corners. */
#ifndef RADIOSITY_ELEMENT_LOOKUP_H
#define RADIOSITY_ELEMENT_LOOKUP_H

inline uint locate_element(__global const ElementNode* nodes, uint patch, float3* w) {
    uint node = patch;
    while (nodes[node].firstChild >= 0) {
        int child;
        float3 v = *w;
        if (v.x >= 0.5f) {
            child = 0;
            v = (float3)(2.0f * v.x - 1.0f, 2.0f * v.y, 2.0f * v.z);
        } else if (v.y >= 0.5f) {
            child = 1;
            v = (float3)(2.0f * v.x, 2.0f * v.y - 1.0f, 2.0f * v.z);
        } else if (v.z >= 0.5f) {
            child = 2;
            v = (float3)(2.0f * v.x, 2.0f * v.y, 2.0f * v.z - 1.0f);
        } else {
            child = 3;
            v = (float3)(1.0f - 2.0f * v.x, 1.0f - 2.0f * v.y, 1.0f - 2.0f * v.z);
        }
        *w = v;
        node = (uint)(nodes[node].firstChild + child);
    }
    return nodes[node].element;
}

#endif
