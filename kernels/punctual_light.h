/* The light a punctual light (shared_types.h: PunctualLight) sends to a point, unoccluded:
 * point and spot lights E = I att cos(theta) / r^2, directional lights E = E_perp cos(theta),
 * where theta is the angle between the receiver's normal and the direction to the light. A
 * spot's attenuation is the glTF specification's recommended smooth cone: with cd the cosine of
 * the angle off its axis, clamp(cd * scale + offset, 0, 1)^2, scale and offset from its inner
 * and outer cone angles (host/light/punctual_lights.cpp). */
#ifndef RADIOSITY_PUNCTUAL_LIGHT_H
#define RADIOSITY_PUNCTUAL_LIGHT_H

#include "host_device.h"
#include "shared_types.h"

/* A spot light's attenuation at cosine cd off its axis: glTF's recommended smooth cone,
 * clamp(cd * scale + offset, 0, 1)^2 (scale and offset from the cone's angles:
 * host/light/punctual_lights.cpp). One definition for the host (the lights' power, sampling and
 * irradiance) and the kernels. */
RAD_HOST_DEVICE rad_real rad_spot_attenuation(rad_real cd, rad_real scale, rad_real offset) {
    const rad_real t = cd * scale + offset;
    const rad_real c = t < RAD_LITERAL(0.0) ? RAD_LITERAL(0.0) : (t > RAD_LITERAL(1.0) ? RAD_LITERAL(1.0) : t);
    return c * c;
}

#ifdef __OPENCL_VERSION__
#include "vector_math.h"

/* Irradiance (W/m^2 per channel) at p, unit normal n, from the light, with nothing in the way.
 * *toLight: the unit direction to the light; *distance: how far it is (0 for a directional
 * light, which is infinitely far). Zero where the light is behind the receiver. */
inline float3 punctual_irradiance(__global const PunctualLight* light, float3 p, float3 n, float3* toLight,
                                  float* distance) {
    const float3 intensity = vload3(0, light->intensity);
    const float3 axis = vload3(0, light->direction);
    if (light->type == RAD_LIGHT_DIRECTIONAL) {
        *toLight = -axis;
        *distance = 0.0f;
        const float c = dot3(n, *toLight);
        return c > 0.0f ? c * intensity : (float3)(0.0f);
    }
    const float3 d = vload3(0, light->position) - p;
    const float r2 = dot3(d, d);
    *distance = sqrt(r2);
    if (!(r2 > 0.0f)) return (float3)(0.0f);
    *toLight = d / *distance;
    const float c = dot3(n, *toLight);
    if (!(c > 0.0f)) return (float3)(0.0f);
    const float attenuation =
        light->type == RAD_LIGHT_SPOT ? rad_spot_attenuation(-dot3(axis, *toLight), light->cone[0], light->cone[1])
                                      : 1.0f;
    return (attenuation * c / r2) * intensity;
}
#endif

#endif
