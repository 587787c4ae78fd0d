/* What the work item of a pixel adds up over its samples, for the sampling kernels (the path
 * tracer, the camera pass's direct and final-gather modes): the radiance summed, the sum of the
 * squares of the samples' luminances (for the pixel's variance), and the rays traced; written,
 * not added, per launch (host/render/pixel_estimate.h adds the launches in double). */
#ifndef RADIOSITY_PIXEL_SUM_H
#define RADIOSITY_PIXEL_SUM_H

typedef struct {
    float3 total;
    float squares;
    uint traced;
} PixelSum;

inline PixelSum pixel_sum_start(void) {
    PixelSum s;
    s.total = (float3)(0.0f);
    s.squares = 0.0f;
    s.traced = 0u;
    return s;
}

inline void pixel_sum_add(PixelSum* s, float3 radiance) {
    s->total += radiance;
    const float lum = (0.2126f * radiance.x + 0.7152f * radiance.y) + 0.0722f * radiance.z;
    s->squares += lum * lum;
}

/* sums[pixel]: the radiance summed (rgb) and the luminances' squares (w); rays[pixel]. */
inline void pixel_sum_write(const PixelSum* s, __global float4* sums, __global uint* rays, uint pixel) {
    sums[pixel] = (float4)(s->total, s->squares);
    rays[pixel] = s->traced;
}

#endif
