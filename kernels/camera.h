/* Primary rays of a pinhole or orthographic camera (CameraRays, shared_types.h): (px, py) in
 * [0, 1)^2 across the image, row 0 at the top. The one mapping both kernels/render.cl (the
 * radiosity image) and kernels/pathtrace.cl (its reference) use, so their pixels match. */
#ifndef RADIOSITY_CAMERA_H
#define RADIOSITY_CAMERA_H

inline float3 camera_ray(const CameraRays* c, float px, float py, float3* origin) {
    const float3 right = vload3(0, c->right), up = vload3(0, c->up), forward = vload3(0, c->forward);
    const float sx = (2.0f * px - 1.0f) * c->right[3];
    const float sy = (1.0f - 2.0f * py) * c->up[3];
    if (c->forward[3] > 0.5f) { /* orthographic: parallel rays from the image plane */
        *origin = vload3(0, c->position) + sx * right + sy * up;
        return forward;
    }
    *origin = vload3(0, c->position);
    return normalize3(forward + sx * right + sy * up);
}

/* The ray through pixel (x, y) of a width x height image at the offset within the pixel given
 * by two 32-bit coordinates (a sample's jitter): the path tracer's and the sampled camera
 * passes' primary rays. Needs rng.h's unit_float. */
inline float3 pixel_ray(const CameraRays* c, uint x, uint y, uint width, uint height, uint2 jitter, float3* origin) {
    const float px = ((float)x + unit_float(jitter.x)) / (float)width;
    const float py = ((float)y + unit_float(jitter.y)) / (float)height;
    return camera_ray(c, px, py, origin);
}

#endif
