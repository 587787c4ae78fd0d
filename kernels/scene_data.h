/* The scene on the device, declared once as a pack (packs.h), as Cycles declares its kernel data
 * in data_arrays.h. Every kernel that traces rays takes the pack as its first parameters and
 * gathers them into one SceneData (RAD_SCENE_DATA) that the material and light functions take,
 * or only its geometry (SceneGeometry, RAD_SCENE_GEOMETRY), which the traversal and the lookups
 * take. The host uploads each array once (the lights again only where an emitter is added after
 * preparing) and binds the pack at each launch (host/device/device_scene.h). A new scene array
 * is one line here and its upload in DeviceScene.
 * Which kernels read what: the BVH's nodes and leaf blocks, every tracing kernel; faces (which
 * patches a hit lands on), kernels that find patches or elements; triangles and cdf (where rays
 * start, by area), kernels that start rays on patches or surfaces; alpha, textureSlots and texels
 * (alpha-masked faces and the textures), the traversal and the camera pass; specular (each face's
 * mirror or glass, one entry when the scene has none: read only in programs built with
 * -DRAD_SPECULAR_TRANSPORT), every kernel that follows mirrors and glass or casts shadow rays;
 * faceMaterials, faceTextures and srgb (what a hit looks like), and the specular layers with their
 * albedo table (faceLayers: one entry unless built with -DRAD_LAYERS; faceSpecularTextures, the
 * layers' KHR_materials_specular textures: one entry unless a face has them; ggxAlbedo: one entry unless
 * built with -DRAD_GGX_TABLE, which layers and rough metals read) and the
 * normal maps (faceNormalMaps: one entry unless built with -DRAD_NORMAL_MAPS), the camera
 * pass, the path tracer and the lightmap; the punctual lights with their tree, the emitting patches sampled for direct
 * light and the environment map's texels and tables, every kernel that computes direct light;
 * info (SceneInfo), all of them. */
#ifndef RADIOSITY_SCENE_DATA_H
#define RADIOSITY_SCENE_DATA_H

#include "packs.h"
#include "shared_types.h"

/* What a ray sees: the BVH, the faces, where rays start (triangles and cdf), the alpha masks with
 * the textures they read, and each face's kind of surface. The traversal and the patch and
 * element lookups read these only (SceneGeometry), so a kernel that only casts rays builds no
 * more than them. */
#define RAD_SCENE_GEOMETRY_ARGS(X)                                                                         \
    X(IN, BvhNode, nodes) X(IN, LeafBlock, blocks) X(IN, FaceInfo, faces) X(IN, SampleTriangle, triangles) \
    X(IN, rad_uint, cdf) X(IN, AlphaFace, alpha) X(IN, TextureSlot, textureSlots) X(IN, rad_uint, texels)  \
    X(IN, SpecularFace, specular)
/* What a hit looks like and the lights. */
#define RAD_SCENE_SHADING_ARGS(X)                                                                             \
    X(IN, FaceMaterial, faceMaterials) X(IN, FaceTexture, faceTextures) X(IN, float, srgb)                    \
    X(IN, PunctualLight, punctualLights) X(IN, LightNode, lightTree) X(IN, SurfaceLight, surfaceLights)       \
    X(IN, rad_uint, surfaceLightEnds) X(IN, rad_uint, lightOfPatch) X(IN, rad_float4, environmentTexels)      \
    X(IN, rad_uint, environmentRows) X(IN, rad_uint, environmentColumns) X(IN, FaceLayer, faceLayers)       \
    X(IN, FaceSpecularTextures, faceSpecularTextures) X(IN, float, ggxAlbedo) X(IN, FaceNormalMap, faceNormalMaps) X(IN, SceneInfo, info)
/* The scene's pack: the geometry's, then the shading's. */
#define RAD_SCENE_ARGS(X) RAD_SCENE_GEOMETRY_ARGS(X) RAD_SCENE_SHADING_ARGS(X)

#ifdef __OPENCL_VERSION__
#define RAD_SCENE_FIELD(kind, type, name) __global const type* name;
#define RAD_SCENE_VALUE(kind, type, name) name,

typedef struct {
    RAD_SCENE_GEOMETRY_ARGS(RAD_SCENE_FIELD)
} SceneGeometry;

/* The geometry, the shading's arrays, and a private copy of the description (read at every hit:
 * kept out of global memory). A function that is not inlined takes its arguments through memory,
 * so the traversal takes the geometry alone: a kernel that casts rays and shades pays for the
 * whole of this once per work item, one that only casts rays (SceneGeometry) for the geometry. */
typedef struct {
    SceneGeometry geometry;
    RAD_SCENE_SHADING_ARGS(RAD_SCENE_FIELD)
    SceneInfo about;
} SceneData;

/* In the body of a kernel whose parameters start with the scene's:
 *   const SceneData scene = RAD_SCENE_DATA;
 * or, where it only casts rays and finds patches and elements:
 *   const SceneGeometry scene = RAD_SCENE_GEOMETRY; */
#define RAD_SCENE_GEOMETRY {RAD_SCENE_GEOMETRY_ARGS(RAD_SCENE_VALUE)}
#define RAD_SCENE_DATA {RAD_SCENE_GEOMETRY, RAD_SCENE_SHADING_ARGS(RAD_SCENE_VALUE) info[0]}
#endif

#endif
