/* The unoccluded form factor from a differential area (point p, unit normal n) to a triangle
 * that emits from its front, by Lambert's closed form: (1 / 2 pi) sum over the edges of the
 * angle each subtends times the cosine between n and the edge's plane. The triangle is first
 * clipped to the half-space in front of p (a polygon partly below p's horizon), and p must be
 * in front of the triangle. Only +, -, *, / and sqrt, so every device gives the same bits: the
 * arctangent is Abramowitz and Stegun's polynomial 4.4.49 (error below 4e-8). */
#ifndef RADIOSITY_POLYGON_FACTOR_H
#define RADIOSITY_POLYGON_FACTOR_H


/* atan(t) for t in [0, 1]. */
inline float atan_unit(float t) {
    const float t2 = t * t;
    return t * (0.9999993329f +
                t2 * (-0.3332985605f +
                      t2 * (0.1994653599f +
                            t2 * (-0.1390853351f +
                                  t2 * (0.0964200441f + t2 * (-0.0559098861f + t2 * (0.0218612288f + t2 * -0.0040540580f)))))));
}

/* The angle in [0, pi] whose sine is y >= 0 and cosine x (up to a common positive factor). */
inline float angle_of(float y, float x) {
    const float ax = fabs(x);
    if (y == 0.0f && ax == 0.0f) return 0.0f;
    float r = atan_unit(fmin(ax, y) / fmax(ax, y));
    if (y > ax) r = 0.5f * RAD_PI - r;
    if (x < 0.0f) r = RAD_PI - r;
    return r;
}

/* Clips the triangle to dot(n, x - p) > 0; returns the vertex count (0, 3 or 4). */
inline int clip_to_horizon(const float3 v[3], float3 p, float3 n, float3 out[4]) {
    int count = 0;
    for (int k = 0; k < 3; ++k) {
        const float3 a = v[k], b = v[k == 2 ? 0 : k + 1];
        const float da = dot3(n, a - p), db = dot3(n, b - p);
        if (da > 0.0f) out[count++] = a;
        if ((da > 0.0f) != (db > 0.0f)) out[count++] = a + (da / (da - db)) * (b - a);
    }
    return count;
}

inline float point_to_triangle_factor(float3 p, float3 n, float3 v0, float3 v1, float3 v2, float3 triangleNormal) {
    if (dot3(triangleNormal, p - v0) <= 0.0f) return 0.0f; /* p is behind the emitting side */
    const float3 v[3] = {v0, v1, v2};
    float3 polygon[4];
    const int count = clip_to_horizon(v, p, n, polygon);
    if (count < 3) return 0.0f;
    float sum = 0.0f;
    for (int k = 0; k < count; ++k) {
        const float3 a = normalize3(polygon[k] - p), b = normalize3(polygon[k + 1 == count ? 0 : k + 1] - p);
        const float3 c = cross3(a, b);
        const float s = sqrt(dot3(c, c));
        if (s > 0.0f) sum += angle_of(s, dot3(a, b)) * (dot3(n, c) / s);
    }
    return fabs(sum) / (2.0f * RAD_PI);
}

#endif
