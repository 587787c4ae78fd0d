/* An element as the kernels that compute light over elements read it (DirectLightElement,
 * host/device/element_records.h): its corners, its normal, how far ray origins are lifted off
 * it, and whether its back is black; and the points of it they start from. */
#ifndef RADIOSITY_ELEMENT_SHAPE_H
#define RADIOSITY_ELEMENT_SHAPE_H

#include "shared_types.h"

typedef struct {
    float3 a, b, c, normal;
    float lift;
    bool blackBack;
} ElementShape;

inline ElementShape element_shape(__global const DirectLightElement* element) {
    ElementShape s;
    s.a = vload3(0, element->corners[0]);
    s.b = vload3(0, element->corners[1]);
    s.c = vload3(0, element->corners[2]);
    s.normal = vload3(0, element->normal);
    s.lift = element->normal[3];
    s.blackBack = element->blackBack != 0u;
    return s;
}

/* The point of weights w (of its second and third corners), lifted off the side of unit normal n. */
inline float3 element_origin(const ElementShape* s, float2 w, float3 n) {
    return s->a + w.x * (s->b - s->a) + w.y * (s->c - s->a) + s->lift * n;
}

#endif
