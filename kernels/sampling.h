/* Mapping uniform samples to points on triangles and to cosine-distributed directions, with
 * only +, -, *, / and sqrt: no built-in transcendental functions, whose precision differs
 * between OpenCL implementations (and PoCL's sin/cos are slow). */
#ifndef RADIOSITY_SAMPLING_H
#define RADIOSITY_SAMPLING_H

#include "shared_math.h" /* RAD_PI, RAD_PI_4 */

/* sin and cos on [-pi/4, pi/4] by their Taylor series to x^9 and x^10: the first omitted
 * terms are below 3e-9 there, under half a float ulp of the results. */
inline float sin_quarter(float x) {
    const float x2 = x * x;
    return x * (1.0f + x2 * (-1.0f / 6.0f + x2 * (1.0f / 120.0f + x2 * (-1.0f / 5040.0f + x2 * (1.0f / 362880.0f)))));
}

inline float cos_quarter(float x) {
    const float x2 = x * x;
    return 1.0f + x2 * (-0.5f + x2 * (1.0f / 24.0f + x2 * (-1.0f / 720.0f +
                                                          x2 * (1.0f / 40320.0f + x2 * (-1.0f / 3628800.0f)))));
}

/* The first share k in [lo, lo + n - 1] whose end lies past x (ends[count - 1] read as 2^32),
 * where it is known to lie: each step halves the range, the same number of steps, ceil(log2 n),
 * for every x, so the work items of a GPU's group step together. */
inline uint share_within(__global const uint* ends, uint lo, uint n, uint x) {
    while (n > 1u) {
        const uint halved = n / 2u;
        lo = ends[lo + halved - 1u] <= x ? lo + halved : lo;
        n -= halved;
    }
    return lo;
}

/* Where x lies within share k, rescaled to [0, 1), as a fresh uniform coordinate. */
inline float within_share(__global const uint* ends, uint count, uint k, uint x) {
    const uint start = k == 0u ? 0u : ends[k - 1u];
    const float width = k + 1u == count ? 4294967296.0f - (float)start : (float)(ends[k] - start);
    return fmin((float)(x - start) / width, 0x1.fffffep-1f);
}

/* The share of 2^32 that the 32-bit coordinate x falls on: ends[k] is the end of share k (the
 * last end, 2^32, is implied); count >= 1. Returns k, and where x lies within share k,
 * rescaled to [0, 1), as a fresh uniform coordinate. */
inline uint pick_share(__global const uint* ends, uint count, uint x, float* rescaled) {
    const uint k = share_within(ends, 0u, count, x);
    *rescaled = within_share(ends, count, k, x);
    return k;
}

/* The bits of a guide to `count` shares' ends (host/util/shares.h: shareGuide): ceil(log2(count)),
 * at most 16. */
inline uint guide_bits(uint count) {
    return count <= 1u ? 0u : min(32u - clz(count - 1u), 16u);
}

/* pick_share's k through the shares' guide: x's part of 2^32 (its top guide_bits) names the
 * share that part starts in, and the next part's the share it ends in; the share x falls on
 * lies between them, most often the same or the next one, where a search of all the ends takes
 * log2(count) dependent steps. */
inline uint pick_guided(__global const uint* ends, __global const uint* guide, uint count, uint x) {
    const uint bits = guide_bits(count);
    if (bits == 0u) return 0u;
    const uint part = x >> (32u - bits);
    const uint lo = guide[part];
    const uint hi = part + 1u < (1u << bits) ? guide[part + 1u] : count - 1u;
    return share_within(ends, lo, hi - lo + 1u, x);
}

/* Share k of the `count` shares whose ends are `ends` (the last end, 2^32, implied). */
inline float share_of(__global const uint* ends, uint count, uint k) {
    /* The width in whole units, before any rounding to float. */
    const uint start = k == 0u ? 0u : ends[k - 1u];
    if (k + 1u == count) return start == 0u ? 1.0f : (float)(0u - start) * 0x1p-32f;
    return (float)(ends[k] - start) * 0x1p-32f;
}

/* Shirley and Chiu's concentric map from the square to the unit disk: area-preserving and
 * low-distortion, so stratified squares stay stratified on the disk. */
inline float2 concentric_disk(float2 u) {
    const float2 c = 2.0f * u - 1.0f;
    if (c.x == 0.0f && c.y == 0.0f) return (float2)(0.0f);
    if (fabs(c.x) > fabs(c.y)) {
        const float phi = RAD_PI_4 * (c.y / c.x);
        return c.x * (float2)(cos_quarter(phi), sin_quarter(phi));
    }
    const float phi = RAD_PI_4 * (c.x / c.y);
    return c.y * (float2)(sin_quarter(phi), cos_quarter(phi));
}

/* Cosine-distributed direction about +z (Malley's method): a uniform disk point lifted to the
 * hemisphere. The pdf is cos(theta) / pi. */
inline float3 cosine_hemisphere(float2 u) {
    const float2 d = concentric_disk(u);
    return (float3)(d.x, d.y, sqrt(fmax(0.0f, 1.0f - d.x * d.x - d.y * d.y)));
}

/* Heitz's low-distortion map from the square to barycentric weights (b1, b2) of v1 and v2,
 * uniform over the triangle ("A Low-Distortion Map Between Triangle and Square", 2019). */
inline float2 triangle_barycentrics(float2 u) {
    if (u.y > u.x) {
        const float b1 = 0.5f * u.x;
        return (float2)(b1, u.y - b1);
    }
    const float b2 = 0.5f * u.y;
    return (float2)(u.x - b2, b2);
}

/* An orthonormal frame (t, b, n) about the unit vector n, without trigonometry or branches on
 * near-zero divisions (Duff et al., "Building an Orthonormal Basis, Revisited", JCGT 2017). */
inline void frame_about(float3 n, float3* t, float3* b) {
    const float sign = n.z >= 0.0f ? 1.0f : -1.0f;
    const float a = -1.0f / (sign + n.z);
    const float c = n.x * n.y * a;
    *t = (float3)(1.0f + sign * n.x * n.x * a, sign * c, -sign * n.x);
    *b = (float3)(c, sign + n.y * n.y * a, -n.y);
}

#endif
