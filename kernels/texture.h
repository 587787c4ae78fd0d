/* Texture lookups on the device, by the host's rules (host/scene/texture_sampling.cpp):
 * KHR_texture_transform, then the sampler's wrap modes, then bilinear filtering (or nearest).
 * Colour texels are decoded from sRGB by a 256-entry table the host computes (the camera pass);
 * alpha is linear (the traversal's alpha masks, bvh_traverse.h). */
#ifndef RADIOSITY_TEXTURE_H
#define RADIOSITY_TEXTURE_H

#include "shared_types.h"

inline int wrap_texel(int i, int size, uint mode) {
    if (mode == RAD_WRAP_CLAMP) return clamp(i, 0, size - 1);
    if (mode == RAD_WRAP_MIRROR) {
        const int period = 2 * size;
        int m = i % period;
        if (m < 0) m += period;
        return m < size ? m : period - 1 - m;
    }
    const int m = i % size;
    return m < 0 ? m + size : m;
}

/* A coordinate brought into one period of its wrap mode first, so texel indices stay small
 * whatever the coordinate (clamping needs only [0, 1] and a margin). */
inline float wrap_coordinate(float t, uint mode) {
    if (!isfinite(t)) return 0.0f; /* a transform that overflowed: the first texel, as the host */
    if (mode == RAD_WRAP_CLAMP) return clamp(t, -1.0f, 2.0f);
    if (mode == RAD_WRAP_MIRROR) return t - 2.0f * floor(0.5f * t);
    return t - floor(t);
}

inline float3 texel_rgb(__global const uint* texels, __global const float* srgb, __global const TextureSlot* slot,
                        int x, int y) {
    const uint t = texels[slot->offset + (uint)y * slot->width + (uint)x];
    if ((slot->flags & 32u) != 0u) /* data (a metallicRoughnessTexture): linear */
        return (float3)((float)(t & 255u), (float)((t >> 8) & 255u), (float)((t >> 16) & 255u)) * (1.0f / 255.0f);
    return (float3)(srgb[t & 255u], srgb[(t >> 8) & 255u], srgb[(t >> 16) & 255u]);
}

inline float texel_alpha(__global const uint* texels, __global const TextureSlot* slot, int x, int y) {
    return (float)(texels[slot->offset + (uint)y * slot->width + (uint)x] >> 24) * (1.0f / 255.0f);
}

/* Where a lookup lands: the four texels around uv (after the transform and wrapping) and the
 * bilinear weights, or one texel (x0, y0) for nearest filtering. */
typedef struct {
    int x0, x1, y0, y1;
    float wx, wy;
    int nearest;
} TexelFootprint;

inline TexelFootprint texel_footprint(__global const TextureSlot* slot, float2 uv) {
    const float u = slot->rows[0][0] * uv.x + slot->rows[0][1] * uv.y + slot->rows[0][2];
    const float v = slot->rows[1][0] * uv.x + slot->rows[1][1] * uv.y + slot->rows[1][2];
    const int w = (int)slot->width, h = (int)slot->height;
    const uint wrapS = slot->flags & 3u, wrapT = (slot->flags >> 2) & 3u;
    const float x = wrap_coordinate(u, wrapS) * (float)w - 0.5f, y = wrap_coordinate(v, wrapT) * (float)h - 0.5f;
    TexelFootprint f;
    f.nearest = (slot->flags & 16u) != 0u;
    if (f.nearest) {
        f.x0 = f.x1 = wrap_texel((int)floor(x + 0.5f), w, wrapS);
        f.y0 = f.y1 = wrap_texel((int)floor(y + 0.5f), h, wrapT);
        f.wx = f.wy = 0.0f;
        return f;
    }
    const float fx = floor(x), fy = floor(y);
    f.wx = x - fx;
    f.wy = y - fy;
    f.x0 = wrap_texel((int)fx, w, wrapS);
    f.x1 = wrap_texel((int)fx + 1, w, wrapS);
    f.y0 = wrap_texel((int)fy, h, wrapT);
    f.y1 = wrap_texel((int)fy + 1, h, wrapT);
    return f;
}

/* The texture's alpha at uv (linear: glTF's alpha is not sRGB-encoded). */
inline float sample_alpha(__global const uint* texels, __global const TextureSlot* slot, float2 uv) {
    const TexelFootprint f = texel_footprint(slot, uv);
    if (f.nearest) return texel_alpha(texels, slot, f.x0, f.y0);
    return (1.0f - f.wy) *
               ((1.0f - f.wx) * texel_alpha(texels, slot, f.x0, f.y0) + f.wx * texel_alpha(texels, slot, f.x1, f.y0)) +
           f.wy *
               ((1.0f - f.wx) * texel_alpha(texels, slot, f.x0, f.y1) + f.wx * texel_alpha(texels, slot, f.x1, f.y1));
}

/* Linear RGB of the texture at uv (before its transform). */
inline float3 sample_texture(__global const uint* texels, __global const float* srgb, __global const TextureSlot* slot,
                             float2 uv) {
    const TexelFootprint f = texel_footprint(slot, uv);
    if (f.nearest) return texel_rgb(texels, srgb, slot, f.x0, f.y0);
    return (1.0f - f.wy) * ((1.0f - f.wx) * texel_rgb(texels, srgb, slot, f.x0, f.y0) +
                            f.wx * texel_rgb(texels, srgb, slot, f.x1, f.y0)) +
           f.wy * ((1.0f - f.wx) * texel_rgb(texels, srgb, slot, f.x0, f.y1) +
                   f.wx * texel_rgb(texels, srgb, slot, f.x1, f.y1));
}

#endif
