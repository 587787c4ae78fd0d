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

#endif
