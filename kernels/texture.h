/* Texture lookups in the camera pass, by the host's rules (host/scene/texture_sampling.cpp):
 * KHR_texture_transform, then the sampler's wrap modes, then bilinear filtering (or nearest) of
 * texels decoded from sRGB by a 256-entry table the host computes. */
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
    if (mode == RAD_WRAP_CLAMP) return clamp(t, -1.0f, 2.0f);
    if (mode == RAD_WRAP_MIRROR) return t - 2.0f * floor(0.5f * t);
    return t - floor(t);
}

inline float3 texel_rgb(__global const uchar4* texels, __global const float* srgb, __global const TextureSlot* slot,
                        int x, int y) {
    const uchar4 t = texels[slot->offset + (uint)y * slot->width + (uint)x];
    return (float3)(srgb[t.x], srgb[t.y], srgb[t.z]);
}

/* Linear RGB of the texture at uv (before its transform). */
inline float3 sample_texture(__global const uchar4* texels, __global const float* srgb,
                             __global const TextureSlot* slot, float2 uv) {
    const float u = slot->rows[0][0] * uv.x + slot->rows[0][1] * uv.y + slot->rows[0][2];
    const float v = slot->rows[1][0] * uv.x + slot->rows[1][1] * uv.y + slot->rows[1][2];
    const int w = (int)slot->width, h = (int)slot->height;
    const uint wrapS = slot->flags & 3u, wrapT = (slot->flags >> 2) & 3u;
    const float x = wrap_coordinate(u, wrapS) * (float)w - 0.5f, y = wrap_coordinate(v, wrapT) * (float)h - 0.5f;
    if ((slot->flags & 16u) != 0u)
        return texel_rgb(texels, srgb, slot, wrap_texel((int)floor(x + 0.5f), w, wrapS),
                         wrap_texel((int)floor(y + 0.5f), h, wrapT));
    const float fx = floor(x), fy = floor(y);
    const float wx = x - fx, wy = y - fy;
    const int x0 = wrap_texel((int)fx, w, wrapS), x1 = wrap_texel((int)fx + 1, w, wrapS);
    const int y0 = wrap_texel((int)fy, h, wrapT), y1 = wrap_texel((int)fy + 1, h, wrapT);
    return (1.0f - wy) *
               ((1.0f - wx) * texel_rgb(texels, srgb, slot, x0, y0) + wx * texel_rgb(texels, srgb, slot, x1, y0)) +
           wy * ((1.0f - wx) * texel_rgb(texels, srgb, slot, x0, y1) + wx * texel_rgb(texels, srgb, slot, x1, y1));
}

#endif
