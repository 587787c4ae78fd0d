/* Kernel argument packs, declared once for the kernel and the host (as Cycles declares its kernel
 * data once in data_arrays.h). A pack is a macro PACK(X) listing entries X(kind, type, name):
 *   IN     a buffer of `type` the kernel reads        (kernel: __global const type* name)
 *   OUT    a buffer of `type` the kernel writes to    (kernel: __global type* name)
 *   VALUE  a value of `type`                           (kernel: type name)
 * A kernel's parameter list is RAD_KERNEL_PARAMS(PACK); the host makes a struct of the same
 * fields from the same list and binds it field by field in the list's order
 * (host/cl/kernel_pack.h), so a parameter moved or added in the list moves on both sides, and
 * the host fills fields by name, never by position. Types are those both sides name alike: the
 * records of shared_types.h, float, rad_uint, rad_int and the vectors below. */
#ifndef RADIOSITY_PACKS_H
#define RADIOSITY_PACKS_H

#include "host_device.h"

#ifdef __OPENCL_VERSION__
typedef float2 rad_float2;
typedef float4 rad_float4;
typedef uint2 rad_uint2;
typedef uint4 rad_uint4;
typedef ulong rad_ulong;

#define RAD_PARAM_IN(type, name) , __global const type* name
#define RAD_PARAM_OUT(type, name) , __global type* name
#define RAD_PARAM_VALUE(type, name) , type name
#define RAD_PARAM(kind, type, name) RAD_PARAM_##kind(type, name)
/* Each entry brings its own leading comma; the first one is dropped. */
#define RAD_DROP_FIRST_(first, ...) __VA_ARGS__
#define RAD_APPLY_(macro, args) macro args
/* __kernel void k(RAD_KERNEL_PARAMS(RAD_K_PACK)) */
#define RAD_KERNEL_PARAMS(PACK) RAD_APPLY_(RAD_DROP_FIRST_, (0 PACK(RAD_PARAM)))
#endif

#endif
