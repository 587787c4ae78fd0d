/* One definition for the host (C++17) and the kernels (OpenCL C 1.2), as pbrt-v4 does with
 * PBRT_CPU_GPU: what is written once under these macros compiles in both, with the same
 * integer and floating-point operations, so host and device agree bit for bit. Headers that
 * both sides include (shared_types.h, shared_math.h, scene_data.h) start here. */
#ifndef RADIOSITY_HOST_DEVICE_H
#define RADIOSITY_HOST_DEVICE_H

#ifdef __OPENCL_VERSION__
#define RAD_HOST_DEVICE inline
/* A literal constant: single precision in the kernels, double on the host. */
#define RAD_LITERAL(x) x##f
typedef uint rad_uint;
typedef int rad_int;
typedef float rad_real; /* the precision each side computes in: float here, double on the host */
#else
#include <cstdint>
#define RAD_HOST_DEVICE inline constexpr
#define RAD_LITERAL(x) x
typedef std::uint32_t rad_uint;
typedef std::int32_t rad_int;
typedef double rad_real;
#endif

#endif
