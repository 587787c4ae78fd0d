/* Constants and integer helpers the host and the kernels share, written once
 * (host_device.h): the hash that keys every sample sequence, and the index of a cell in a
 * face's patch grid. The host includes this file as it is; nothing here may differ between
 * the two sides. */
#ifndef RADIOSITY_SHARED_MATH_H
#define RADIOSITY_SHARED_MATH_H

#include "host_device.h"

#define RAD_PI RAD_LITERAL(3.14159265358979323846)
#define RAD_PI_4 RAD_LITERAL(0.78539816339744830962)

/* A 32-bit integer hash with good avalanche (Wellons's "lowbias32"). */
RAD_HOST_DEVICE rad_uint rad_hash(rad_uint x) {
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}

/* Two keys to one: a sequence keyed by (seed, stream) or (stream, source). */
RAD_HOST_DEVICE rad_uint rad_hash2(rad_uint a, rad_uint b) { return rad_hash(a ^ rad_hash(b + 0x9e3779b9u)); }

/* A face split into n * n similar triangles (host/mesh/patch_grid.h): row b holds the "up"
 * cells (a, b) for a = 0 .. n-1-b and, between them, the "down" cells (down = 1) for
 * a = 0 .. n-2-b. The index of a cell within the face. */
RAD_HOST_DEVICE rad_uint rad_grid_index(rad_uint n, rad_uint a, rad_uint b, rad_uint down) {
    return 2u * n * b - b * b + 2u * a + down;
}

#ifndef __OPENCL_VERSION__
namespace rad {
inline constexpr double kPi = RAD_PI;
}  // namespace rad
#endif

#endif
