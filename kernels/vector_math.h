/* dot, cross and normalize written out. The built-ins' precision and evaluation order are the
 * implementation's to choose (and may fuse multiplies and adds); these give the same bits on
 * every device, so results do not depend on which OpenCL implementation runs them. */
#ifndef RADIOSITY_VECTOR_MATH_H
#define RADIOSITY_VECTOR_MATH_H

inline float dot3(float3 a, float3 b) { return (a.x * b.x + a.y * b.y) + a.z * b.z; }

inline float3 cross3(float3 a, float3 b) {
    return (float3)(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}

inline float3 normalize3(float3 v) { return v / sqrt(dot3(v, v)); }

/* The largest magnitude among v's components (the scale of a point's rounding). */
inline float max_abs3(float3 v) { return fmax(fmax(fabs(v.x), fabs(v.y)), fabs(v.z)); }

#endif
