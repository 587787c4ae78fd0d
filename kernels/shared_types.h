/* Structures shared by the host (C++) and the kernels (OpenCL C 1.2). Only fixed-size arrays
 * of 32-bit scalars, so both compilers lay them out the same; the host checks the sizes with
 * static_assert. Kernels read float4 / float8 out of them with vload4 / vload8. */
#ifndef RADIOSITY_SHARED_TYPES_H
#define RADIOSITY_SHARED_TYPES_H

#include "host_device.h"
#include "material_kinds.h"

#define RAD_BVH_WIDTH 8
#define RAD_LEAF_SIZE 4
/* Entries of the private traversal stack; the host refuses a BVH that could need more. */
#define RAD_STACK_SIZE 96
#define RAD_NO_PATCH 0xFFFFFFFFu

/* The progressive solve's shots mark, for every element that received power in a batch, its
 * block of 2^RAD_TOUCHED_SHIFT elements (touched[e >> RAD_TOUCHED_SHIFT] = 1), so that the
 * gather reads and clears only those elements' counters: a batch's work follows its rays, not
 * the element count. Every writer stores the same 1, so the marks do not depend on the order. */
#define RAD_TOUCHED_SHIFT 6u
/* A child slot that holds nothing. Its bounds are inverted so no ray ever enters it. */
#define RAD_EMPTY_CHILD 0x7FFFFFFF
/* A leaf is a run of 1 to 4 consecutive leaf blocks; a child slot links to it as
 * ~(first block * 4 + blocks - 1), which is negative. */
#define RAD_LEAF_LINK(first, count) (~(rad_int)(((first) << 2) | ((count) - 1u)))
#define RAD_LEAF_FIRST(link) ((~(link)) >> 2)
#define RAD_LEAF_COUNT(link) (((~(link)) & 3) + 1)
#define RAD_MAX_LEAF_BLOCKS 4
#define RAD_MAX_LEAF_BLOCK (1u << 29)

/* One node of the 8-wide BVH: the children's boxes side by side (structure of arrays) so one
 * float8 operation tests all eight. child >= 0: an inner node; child < 0: a leaf
 * (RAD_LEAF_LINK). */
typedef struct {
    float lo[3][RAD_BVH_WIDTH]; /* lo[axis][child] */
    float hi[3][RAD_BVH_WIDTH];
    rad_int child[RAD_BVH_WIDTH];
} BvhNode; /* 224 bytes */

/* Up to four faces, one per float4 lane, for one SIMD watertight triangle test. */
typedef struct {
    float v[3][3][RAD_LEAF_SIZE]; /* v[vertex][axis][lane] */
    rad_int face[RAD_LEAF_SIZE];  /* -1 in lanes that hold nothing */
} LeafBlock; /* 160 bytes */

/* Where a face's patches are. The face is split into n * n cells (host/mesh/patch_grid.h). */
typedef struct {
    rad_uint frontPatch;  /* first patch of the front side */
    rad_uint backPatch;   /* first patch of the back side, or RAD_NO_PATCH: the back is black */
    rad_uint subdivision; /* n */
    rad_uint alpha;       /* its AlphaFace in the scene's list, or 0: opaque */
    float normal[4];      /* unit front normal; w unused */
} FaceInfo; /* 32 bytes */

/* A triangle rays start from, on its emitting side: v0, v0 + e1, v0 + e2. The device's array
 * holds every patch (at its patch index), then each surface side's faces. */
typedef struct {
    float v0[4];      /* w: how far ray origins are lifted off the triangle, metres */
    float e1[4];
    float e2[4];
    float normal[4];  /* unit normal of the emitting side; w: area, m^2 */
    float tangent[4]; /* unit vector along e1, spanning the local frame with the normal; w: how far
                         (in barycentric terms) ray origins keep from the edges */
} SampleTriangle; /* 80 bytes */

/* Rays from one source within one launch. A source is one triangle (triangleCount == 1) or a
 * run of triangles sampled in proportion to area through cdf[firstTriangle ..], with the run's
 * guide to that table at cdf[guide ..] (host/util/shares.h: shareGuide). Its rays take
 * the sample indices firstSample .. firstSample + rayCount - 1 of the sequence keyed by
 * `scramble`, so a source split across launches continues one stratified sequence. */
typedef struct {
    rad_uint firstTriangle;
    rad_uint triangleCount;
    rad_uint firstRay;    /* index of this source's first ray in the launch */
    rad_uint rayCount;
    rad_uint firstSample;
    rad_uint scramble;
    rad_uint row;         /* row of the count matrix that receives the hits */
    rad_uint guide;       /* where the run's guide starts in cdf (a run of more than one triangle) */
} RaySource; /* 32 bytes */

/* A node of the element quadtrees. Node p (p < patchCount) is patch p's root; a node with
 * children has firstChild >= 0, the first of four consecutive nodes (host/mesh/elements.h);
 * a leaf has firstChild < 0 and names its element. */
typedef struct {
    rad_int firstChild;
    rad_uint element;
} ElementNode; /* 8 bytes */

/* One shooter of a progressive-refinement batch. Every one of its rays carries the same power,
 * in fixed point: weight[2c] + 2^32 weight[2c + 1] quanta of channel c (the quantum is the
 * solver's, a tiny fraction of the emitted power), added with integer atomics so the sums do
 * not depend on the order rays finish in. `taken` is what its rays carry in all, per channel,
 * in W: what leaves its unshot power. */
typedef struct {
    rad_uint weight[6];
    rad_uint patch;
    rad_uint rays;
    float taken[4];
} Shooter; /* 48 bytes */

/* What each work item of the gather kernel reports on its share of the clusters of patches
 * (mesh/patch_clusters.h): the sum of the magnitudes of their patches' unshot power
 * (|r| + |g| + |b|), its signed sum per channel (sums; w unused), and the cluster with the most
 * power to shoot (its patches' unshot power plus the overshoot), with that power per channel
 * (w: its magnitude; -1 when the share holds no cluster). */
typedef struct {
    float largest[4];
    float sums[4];
    float unshotSum;
    rad_uint largestCluster;
    rad_uint pad[2];
} UnshotPartial; /* 48 bytes */

/* A pinhole or orthographic camera for the render kernel. */
typedef struct {
    float position[4];
    float right[4];    /* unit; w: tan(yfov / 2) * aspect for perspective, half width for orthographic */
    float up[4];       /* unit; w: tan(yfov / 2), or half height */
    float forward[4];  /* unit, the viewing direction; w: 1 for orthographic, 0 for perspective */
} CameraRays; /* 64 bytes */

/* A punctual light (host/light/punctual_lights.h): a point or spot light at `position`, or a
 * directional light from infinitely far against `direction`. */
#define RAD_LIGHT_POINT 0u
#define RAD_LIGHT_SPOT 1u
#define RAD_LIGHT_DIRECTIONAL 2u
typedef struct {
    float position[4];  /* xyz: where it is (point, spot); w unused */
    float direction[4]; /* xyz: unit, the way its light travels (spot axis, directional); w unused */
    float intensity[4]; /* rgb: W/sr (point, spot) or W/m^2 (directional); w: luminance of rgb */
    float cone[4];      /* spot: attenuation clamp(cos(angle) * x + y, 0, 1)^2 about the axis */
    rad_uint type;      /* RAD_LIGHT_POINT, RAD_LIGHT_SPOT or RAD_LIGHT_DIRECTIONAL */
    rad_uint pad[3];
} PunctualLight; /* 80 bytes */

/* A material's texture as the kernels read it (host/device/device_textures.h): its texels'
 * place in the scene's texel buffer (one rad_uint per texel: 8-bit R, G, B, A from the lowest
 * byte; sRGB colour, linear alpha; rows from the top), size, sampler and KHR_texture_transform
 * (uv' = (rows[0] . (u, v, 1), rows[1] . (u, v, 1))). */
#define RAD_WRAP_REPEAT 0u
#define RAD_WRAP_CLAMP 1u
#define RAD_WRAP_MIRROR 2u
typedef struct {
    rad_uint offset; /* first texel */
    rad_uint width, height;
    rad_uint flags;   /* bits 0-1: wrap s; 2-3: wrap t; 4: nearest; 5: linear data (no sRGB decoding) */
    float rows[2][4]; /* the transform's first two rows; w unused */
} TextureSlot;        /* 48 bytes */

/* An alpha-masked face (alphaMode MASK): rays pass through it where baseColorFactor.a times
 * the base colour texture's alpha at the hit is below the cutoff. The scene's list starts with
 * a header whose `count` says how many faces follow (0: no face is masked). FaceInfo::alpha
 * indexes the list (0: not masked). */
typedef struct {
    rad_int slot;   /* the base colour texture's TextureSlot, or -1: the factor alone */
    float factor;   /* baseColorFactor.a */
    float cutoff;   /* alphaCutoff */
    rad_uint count; /* the header's: masked faces in the list; 0 elsewhere */
    float uv[8];    /* (u, v) of corners 0, 1, 2 in the texture's set; the last two unused */
} AlphaFace;        /* 48 bytes */

/* A textured face: its corners' texture coordinates for the base colour and emissive textures,
 * which slots those are (-1: none), and the factors they multiply; and where the mesh gives
 * vertex colours (glTF's COLOR_0, which multiplies the base colour), its corners' colours. */
typedef struct {
    float baseUv[8]; /* (u, v) of corners 0, 1, 2; the last two unused */
    float emissiveUv[8];
    float reflectance[4]; /* rgb: the material's diffuse reflectance (texture and colours aside) */
    float emission[4];    /* rgb: the material's emitted radiance Le (texture aside) */
    rad_int baseSlot, emissiveSlot;
    rad_uint coloured; /* 1: colours holds the corners' vertex colours */
    rad_uint pad;
    float colours[12]; /* rgb of corners 0, 1, 2 (linear); w unused */
} FaceTexture; /* 160 bytes */

/* An emitting patch that the camera pass and the path tracer sample for direct light
 * (host/light/light_sampling.h, kernels/surface_lights.h): its triangle (SampleTriangle, on the
 * emitting side) and its emitted radiance. */
typedef struct {
    float radiance[4];  /* rgb: Le, W/m^2/sr; w unused (the triangle's area is its SampleTriangle's) */
    rad_uint triangle;  /* its SampleTriangle: the patch's index */
    rad_uint pad[3];
} SurfaceLight;         /* 32 bytes */

/* What a face does with light other than reflect it diffusely (scene/surface_kinds.h,
 * kernels/material.h): its kind (material_kinds.h; RAD_SPECULAR_NONE: diffuse), colour and
 * parameter, its roughness where glass is rough, and its corners' shading normals. The scene has
 * one per face where any face is not diffuse, else one entry. */
typedef struct {
    float colour[4];     /* rgb: the metal's F0, or glass's tint; w: glass's IOR, or a rough metal's GGX alpha */
    float normals[3][4]; /* unit shading normals at the face's corners (the front's sense) */
    float attenuation[4]; /* rgb: a solid glass's attenuation coefficient inside, per metre (0: clear); w unused */
    rad_uint kind;
    float alpha;         /* glass: its GGX alpha (0: smooth) */
    rad_uint pad[2];
} SpecularFace;          /* 96 bytes */

/* A node of the punctual lights' tree (host/light/light_tree.h): the box around its lights'
 * positions, their summed intensity, its representative (its brightest light, by luminance)
 * and its children. Point and spot lights only; directional lights stand apart. */
typedef struct {
    float lo[4]; /* w: luminance of `intensity` */
    float hi[4];
    float intensity[4]; /* rgb: summed radiant intensity, W/sr */
    rad_int left;       /* child nodes, or for a leaf left = -1 - its light's index */
    rad_int right;
    rad_int rep; /* index of the representative light */
    rad_uint pad;
} LightNode; /* 64 bytes */

/* The light from outside the scene (host/scene/environment_map.h, kernels/environment.h): with
 * width 0, the same radiance `sky` from every direction (a uniform sky, or black); else an
 * equirectangular map of width x height texels with its sampling tables. */
typedef struct {
    float sky[4]; /* rgb: radiance, W/m^2/sr, where width is 0 */
    rad_uint width;
    rad_uint height;
    rad_uint pad[2];
} EnvironmentInfo; /* 32 bytes */

/* What the scene's kernels read besides its arrays (host/device/device_scene.h): the light from
 * outside, how many punctual lights and emitting patches the light-sampling arrays hold, whether
 * faces have textures, and how far a ray continued from a surface leaves it. */
typedef struct {
    EnvironmentInfo environment;
    rad_uint punctualCount;     /* PunctualLight records */
    rad_uint directional;       /* of them, the directional ones, listed first */
    rad_uint surfaceLightCount; /* SurfaceLight records (0: no emitting patch is sampled) */
    rad_uint textured;          /* 1: faceTextures holds one FaceTexture per face */
    float lift;                 /* the least distance a continued ray's origin leaves a surface by, m */
    rad_uint pad[3];
} SceneInfo; /* 64 bytes */

/* glTF's specular layer over a diffuse face (host/scene/material_model.h: SurfaceLayer). At a hit
 * of base colour `base` (FaceMaterial, FaceTexture) and metallic m, roughness r (the factors times
 * the metallicRoughnessTexture's blue and green there, where it has one; r at least 0.05): one
 * GGX lobe (alpha = r^2) with the Fresnel factor F0 + (F90 - F0) (1 - c)^5, F0 = (1 - m) dF0 +
 * m base, F90 = (1 - m) dF90 + m, over a diffuse part of colour base (1 - m)(1 - transmission),
 * which reflects toward a direction of cosine mu the share 1 - Ed(mu) the dielectric's layer
 * leaves it (Ed = dF0 E1 + (dF90 - dF0) E5, from the albedo table, host/scene/ggx_albedo.h). A
 * layer is drawn about the normal interpolated from its corners' (the face's own where flat).
 * One per face in programs built with -DRAD_LAYERS (kernels/material.h), else one entry. */
#define RAD_ALBEDO_COSINES 32u   /* the albedo table's cosines, (i / 31)^2 (host/scene/ggx_albedo.h) */
#define RAD_ALBEDO_ROUGHNESS 32u /* and roughnesses, j / 31; then each roughness's hemispherical means */
typedef struct {
    float normals[3][4];  /* the corners' unit shading normals; w unused */
    float dielectric[4];  /* rgb: the dielectric's F0 (dF0); w: its F90 (dF90) */
    float factors[4];     /* metallic, roughness, 1 - transmission, and 1 where the face has a layer (else 0) */
    float metalUv[8];     /* (u, v) of corners 0, 1, 2 in the metallicRoughnessTexture's set; the last two unused */
    rad_int metalSlot;    /* its TextureSlot, or -1: the factors alone */
    rad_int specularTextures; /* its FaceSpecularTextures, or -1: `dielectric` holds dF0 and dF90 */
    rad_uint pad[2];
} FaceLayer; /* 128 bytes */

/* A layered face's KHR_materials_specular textures (FaceLayer::specularTextures): there, dF0 is
 * min(colour, 1) s and dF90 s, colour = specular.rgb times the specularColorTexture's rgb and
 * s = specular.w times the specularTexture's alpha (each texture where it has one). A table of
 * its own, one entry when no face has them, so the layers of scenes without them stay small. */
typedef struct {
    float specular[4];        /* rgb: F0(ior) times specularColorFactor, unclamped; w: specularFactor */
    float strengthUv[8];      /* (u, v) of corners 0, 1, 2 in the specularTexture's set; the last two unused */
    float colourUv[8];        /* and in the specularColorTexture's */
    rad_int strengthSlot;     /* the specularTexture's TextureSlot, or -1 */
    rad_int colourSlot;       /* the specularColorTexture's, or -1 */
    rad_uint pad[2];
} FaceSpecularTextures; /* 96 bytes */

/* A face's normal map (glTF's normalTexture; host/device/face_normal_maps.h, kernels/material.h:
 * mapped_normal). At a hit the normal, the tangent and the texture coordinates are interpolated
 * from the corners'; the texel's (2 rgb - 1), its x and y times `scale`, in the frame (tangent,
 * cross(normal, tangent) w, normal) is the normal the face is shaded by (glTF's convention: x
 * along increasing u, y up the image). One per face in programs built with -DRAD_NORMAL_MAPS,
 * else one entry. */
typedef struct {
    float normals[3][4];  /* the corners' unit normals (the face's own where it is flat); w unused */
    float tangents[3][4]; /* xyz: the corners' unit tangents; w: +-1, the bitangent's sign */
    float uv[8];          /* (u, v) of corners 0, 1, 2 in the normal texture's set; the last two unused */
    rad_int slot;         /* the texture's TextureSlot, or -1: the face has no normal map */
    float scale;          /* normalTexture.scale */
    rad_uint pad[2];
} FaceNormalMap; /* 144 bytes */

/* A face's diffuse reflectance and emitted radiance: its front patch's (the texture's mean over
 * the patch where it has one; kernels/material.h (material_at) reads the texture itself). */
typedef struct {
    float reflectance[4]; /* rgb; w unused */
    float emission[4];    /* rgb: Le, W/m^2/sr; w unused */
} FaceMaterial; /* 32 bytes */

/* An element as the kernels that compute light over elements read it (host/device/
 * element_records.h: kernels/direct_light.cl, view_pass.cl's element_indirect). */
typedef struct {
    float corners[3][4];   /* xyz; w unused */
    float normal[4];       /* unit normal of its patch; w: how far ray origins are lifted off it, m */
    float faceWeights[3][2]; /* the corners' barycentric weights (b1, b2) in their face, for its alpha mask */
    rad_uint face;
    rad_uint blackBack;    /* 1: its face's back is black (light arriving there is absorbed) */
} DirectLightElement; /* 96 bytes */

/* An element as adaptive refinement's direct light reads it (kernels/refine.cl): its corners,
 * lifted off the surface as ray origins are, and its unit normal. */
typedef struct {
    float corners[3][4]; /* xyz; w unused */
    float normal[4];     /* w unused */
} LiftedElement; /* 64 bytes */

/* A piece of a lightmap texel's footprint (host/lightmap/texel_footprints.h): the part of one
 * face that lies in the texel, as a triangle in the face's barycentric coordinates ((b1, b2),
 * the weights of its corners 1 and 2, at each of the piece's corners). A texel's pieces are
 * listed together, `end` their running share of its surface area (the last piece's is 1), so a
 * uniform number picks a piece in proportion to its area. */
typedef struct {
    float b[3][2];
    float end;
    rad_uint face;
} TexelPiece; /* 32 bytes */

/* In a lightmap's per-face chart numbers (kernels/lightmap.cl): the face is baked on its back. */
#define RAD_LIGHTMAP_BACK 0x80000000u

/* The point of a lightmap texel's footprint nearest the texel's centre (the centre itself where
 * the footprint holds it): the side of any contact the texel stands for. A sample counts only
 * if the surface reaches it from here without passing another chart (kernels/lightmap.cl). */
typedef struct {
    float b1, b2; /* in the face's barycentrics */
    rad_uint face;
    rad_uint pad;
} TexelAnchor; /* 16 bytes */

/* The host compiles these records too: each must have the size the kernels give it (only
 * 32-bit scalars and arrays of them, so both compilers lay them out alike). */
#ifndef __OPENCL_VERSION__
static_assert(sizeof(BvhNode) == 224, "BvhNode must match the kernels' layout");
static_assert(sizeof(LeafBlock) == 160, "LeafBlock must match the kernels' layout");
static_assert(sizeof(FaceInfo) == 32, "FaceInfo must match the kernels' layout");
static_assert(sizeof(SampleTriangle) == 80, "SampleTriangle must match the kernels' layout");
static_assert(sizeof(RaySource) == 32, "RaySource must match the kernels' layout");
static_assert(sizeof(ElementNode) == 8, "ElementNode must match the kernels' layout");
static_assert(sizeof(Shooter) == 48, "Shooter must match the kernels' layout");
static_assert(sizeof(UnshotPartial) == 48, "UnshotPartial must match the kernels' layout");
static_assert(sizeof(CameraRays) == 64, "CameraRays must match the kernels' layout");
static_assert(sizeof(PunctualLight) == 80, "PunctualLight must match the kernels' layout");
static_assert(sizeof(TextureSlot) == 48, "TextureSlot must match the kernels' layout");
static_assert(sizeof(AlphaFace) == 48, "AlphaFace must match the kernels' layout");
static_assert(sizeof(FaceTexture) == 160, "FaceTexture must match the kernels' layout");
static_assert(sizeof(SurfaceLight) == 32, "SurfaceLight must match the kernels' layout");
static_assert(sizeof(SpecularFace) == 96, "SpecularFace must match the kernels' layout");
static_assert(sizeof(LightNode) == 64, "LightNode must match the kernels' layout");
static_assert(sizeof(EnvironmentInfo) == 32, "EnvironmentInfo must match the kernels' layout");
static_assert(sizeof(SceneInfo) == 64, "SceneInfo must match the kernels' layout");
static_assert(sizeof(FaceMaterial) == 32, "FaceMaterial must match the kernels' layout");
static_assert(sizeof(FaceLayer) == 128, "FaceLayer must match the kernels' layout");
static_assert(sizeof(FaceSpecularTextures) == 96, "FaceSpecularTextures must match the kernels' layout");
static_assert(sizeof(FaceNormalMap) == 144, "FaceNormalMap must match the kernels' layout");
static_assert(sizeof(DirectLightElement) == 96, "DirectLightElement must match the kernels' layout");
static_assert(sizeof(LiftedElement) == 64, "LiftedElement must match the kernels' layout");
static_assert(sizeof(TexelPiece) == 32, "TexelPiece must match the kernels' layout");
static_assert(sizeof(TexelAnchor) == 16, "TexelAnchor must match the kernels' layout");
#endif

#endif
