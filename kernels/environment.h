/* The light from outside the scene, as the kernels see it: a uniform radiance, or an
 * equirectangular map (host/scene/environment_map.h gives the mapping, Blender's, and the
 * host's twin of every function here). Directions map to the image by an arctangent of our
 * own, from +, -, *, / and sqrt only, so every OpenCL implementation finds the same texels.
 *
 * Sampling: environment_sample draws a direction in proportion to the light the map brings
 * (a row by the host's row table, a texel within it by the row's column table, then uniformly
 * in solid angle within the texel), and environment_pdf says with what density a direction is
 * drawn, so estimators can combine it with cosine sampling (multiple importance sampling). */
#ifndef RADIOSITY_ENVIRONMENT_H
#define RADIOSITY_ENVIRONMENT_H

#include "sampling.h" /* pick_share, share_of, sin_quarter, cos_quarter */
#include "scene_data.h"

/* The environment's buffers and description, as one value for the functions below. */
typedef struct {
    EnvironmentInfo info;
    __global const float4* texels;  /* width * height radiances, row 0 at the top */
    __global const uint* rows;      /* the row table: height ends of shares of 2^32 */
    __global const uint* columns;   /* each row's table: width ends */
} Environment;

/* The scene's environment (the sky, a map, or black). */
inline Environment scene_environment(const SceneData* scene) {
    const Environment env = {scene->about.environment, scene->environmentTexels, scene->environmentRows,
                             scene->environmentColumns};
    return env;
}

/* atan(y) for |y| <= tan(pi/8), by its series to y^17: the first omitted term is below 3e-9. */
inline float atan_reduced(float y) {
    const float y2 = y * y;
    float sum = 1.0f / 17.0f;
    sum = -1.0f / 15.0f + y2 * sum;
    sum = 1.0f / 13.0f + y2 * sum;
    sum = -1.0f / 11.0f + y2 * sum;
    sum = 1.0f / 9.0f + y2 * sum;
    sum = -1.0f / 7.0f + y2 * sum;
    sum = 1.0f / 5.0f + y2 * sum;
    sum = -1.0f / 3.0f + y2 * sum;
    return y * (1.0f + y2 * sum);
}

/* atan(x) for 0 <= x <= 1, reduced by atan(x) = pi/4 + atan((x - 1) / (x + 1)). */
inline float atan_unit(float x) {
    if (x <= 0.41421356f) return atan_reduced(x);
    return RAD_PI_4 + atan_reduced((x - 1.0f) / (x + 1.0f));
}

/* atan2(y, x) in [-pi, pi]; 0 for (0, 0). */
inline float env_atan2(float y, float x) {
    const float ax = fabs(x), ay = fabs(y);
    if (ax == 0.0f && ay == 0.0f) return 0.0f;
    float a = ay <= ax ? atan_unit(ay / ax) : 0.5f * RAD_PI - atan_unit(ax / ay);
    if (x < 0.0f) a = RAD_PI - a;
    return y < 0.0f ? -a : a;
}

/* (sin a, cos a) for |a| <= 2 pi: reduced to [-pi/4, pi/4] by quarter turns. */
inline float2 env_sincos(float a) {
    const float quarters = floor(a * (2.0f / RAD_PI) + 0.5f);
    /* pi/2 in two parts, so the reduction loses nothing at these magnitudes. */
    const float r = (a - quarters * 1.5707963705062866f) + quarters * 4.371139000186243e-8f;
    const float s = sin_quarter(r), c = cos_quarter(r);
    const int k = ((int)quarters % 4 + 4) % 4;
    if (k == 0) return (float2)(s, c);
    if (k == 1) return (float2)(c, -s);
    if (k == 2) return (float2)(-s, -c);
    return (float2)(-c, s);
}

/* The map coordinates (u across from the left, t down from the top) of unit direction d. */
inline float2 environment_coordinates(float3 d) {
    const float u = 0.5f + env_atan2(d.z, d.x) * (0.5f / RAD_PI);
    const float sine = sqrt(fmax(0.0f, (1.0f - d.y) * (1.0f + d.y)));
    const float t = env_atan2(sine, d.y) * (1.0f / RAD_PI);
    return (float2)(fmin(fmax(u, 0.0f), 1.0f), fmin(fmax(t, 0.0f), 1.0f));
}

/* The radiance arriving from unit direction d: bilinear between texel centres, wrapping across
 * the left and right edges, clamped at the top and bottom rows. */
inline float3 environment_radiance(const Environment* env, float3 d) {
    if (env->info.width == 0u) return vload3(0, env->info.sky);
    const int w = (int)env->info.width, h = (int)env->info.height;
    const float2 ut = environment_coordinates(d);
    const float x = ut.x * (float)w - 0.5f, y = ut.y * (float)h - 0.5f;
    const float x0 = floor(x), y0 = floor(y);
    const float fx = x - x0, fy = y - y0;
    int xa = (int)x0, xb = xa + 1;
    if (xa < 0) xa += w;
    if (xb >= w) xb -= w;
    const int ya = clamp((int)y0, 0, h - 1), yb = clamp((int)y0 + 1, 0, h - 1);
    const float3 top = (1.0f - fx) * env->texels[ya * w + xa].xyz + fx * env->texels[ya * w + xb].xyz;
    const float3 bottom = (1.0f - fx) * env->texels[yb * w + xa].xyz + fx * env->texels[yb * w + xb].xyz;
    return (1.0f - fy) * top + fy * bottom;
}

/* cos(theta) at the top of row y of h, and the difference down to its bottom (computed as
 * 2 sin(mid) sin(half), which keeps its precision near the poles). */
inline float2 row_cosines(uint y, uint h) {
    const float top = env_sincos(RAD_PI * (float)y / (float)h).y;
    const float drop = 2.0f * env_sincos(RAD_PI * ((float)y + 0.5f) / (float)h).x * env_sincos(0.5f * RAD_PI / (float)h).x;
    return (float2)(top, drop);
}

/* The solid angle of a texel of row y. */
inline float texel_solid_angle(const Environment* env, uint y) {
    return 2.0f * RAD_PI / (float)env->info.width * row_cosines(y, env->info.height).y;
}

/* The density (per steradian) with which environment_sample draws unit direction d. */
inline float environment_pdf(const Environment* env, float3 d) {
    const uint w = env->info.width, h = env->info.height;
    const float2 ut = environment_coordinates(d);
    const uint x = min((uint)(ut.x * (float)w), w - 1u), y = min((uint)(ut.y * (float)h), h - 1u);
    const float p = share_of(env->rows, h, y) * share_of(env->columns + (size_t)y * w, w, x);
    return p / texel_solid_angle(env, y);
}

/* A direction drawn from the map's tables by two 32-bit coordinates, and its density. */
inline float3 environment_sample(const Environment* env, uint2 r, float* pdf) {
    const uint w = env->info.width, h = env->info.height;
    float fy, fx;
    const uint y = pick_share(env->rows, h, r.x, &fy);
    const uint x = pick_share(env->columns + (size_t)y * w, w, r.y, &fx);
    const float2 rows = row_cosines(y, h);
    const float cosTheta = rows.x - fy * rows.y;
    const float sinTheta = sqrt(fmax(0.0f, (1.0f - cosTheta) * (1.0f + cosTheta)));
    const float2 phi = env_sincos(2.0f * RAD_PI * (((float)x + fx) / (float)w - 0.5f));
    *pdf = share_of(env->rows, h, y) * share_of(env->columns + (size_t)y * w, w, x) /
           (2.0f * RAD_PI / (float)w * rows.y);
    return (float3)(sinTheta * phi.y, cosTheta, sinTheta * phi.x);
}

#endif
