/* The scene's buffers on the device, declared once (as Cycles declares its kernel data in
 * data_arrays.h). Every kernel that traces rays takes them as its first parameters, in this
 * order (RAD_SCENE_PARAMS), and gathers them into one SceneData (RAD_SCENE_DATA) that the
 * traversal and lookup functions take. The host holds and binds them from the same list
 * (host/prepared/device_scene.h), once per kernel object. A new scene buffer is one line here,
 * and its upload in DeviceScene's constructor.
 * Which kernels read what: the BVH's nodes and leaf blocks, every tracing kernel; faces (which
 * patches a hit lands on), kernels that find patches or elements; triangles and cdf (where rays
 * start, by area), kernels that start rays on patches or surfaces; alpha, textureSlots and
 * texels (alpha-masked faces and the textures), the traversal and the camera pass; specular (each
 * face's mirror or glass, one entry when the scene has none: read only in programs built with
 * -DRAD_SPECULAR_TRANSPORT), every kernel that follows mirrors and glass or casts shadow rays. */
#ifndef RADIOSITY_SCENE_DATA_H
#define RADIOSITY_SCENE_DATA_H

#include "shared_types.h"

/* X(element type, name) */
#define RAD_SCENE_BUFFERS(X)     \
    X(BvhNode, nodes)            \
    X(LeafBlock, blocks)         \
    X(FaceInfo, faces)           \
    X(SampleTriangle, triangles) \
    X(rad_uint, cdf)             \
    X(AlphaFace, alpha)          \
    X(TextureSlot, textureSlots) \
    X(rad_uint, texels)          \
    X(SpecularFace, specular)

#ifdef __OPENCL_VERSION__
#define RAD_SCENE_PARAM(type, name) __global const type* name,
#define RAD_SCENE_FIELD(type, name) __global const type* name;
#define RAD_SCENE_VALUE(type, name) name,

/* A kernel's first parameters; the kernel's own follow (the macro ends with a comma). */
#define RAD_SCENE_PARAMS RAD_SCENE_BUFFERS(RAD_SCENE_PARAM)

typedef struct {
    RAD_SCENE_BUFFERS(RAD_SCENE_FIELD)
} SceneData;

/* In the kernel's body: const SceneData scene = RAD_SCENE_DATA; */
#define RAD_SCENE_DATA {RAD_SCENE_BUFFERS(RAD_SCENE_VALUE)}
#endif

#endif
