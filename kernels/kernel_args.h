/* Every kernel's parameters, declared once for the kernel and the host (packs.h says how). A
 * kernel that traces rays takes the scene's pack first (scene_data.h: RAD_SCENE_ARGS), then its
 * own; its full list is named RAD_<KERNEL>_KERNEL and its own pack RAD_<KERNEL>_ARGS, which the
 * host binds as the struct host/device/kernel_arguments.h makes of it. Each pack is one line, as
 * the kernel's signature would be. */
#ifndef RADIOSITY_KERNEL_ARGS_H
#define RADIOSITY_KERNEL_ARGS_H

#include "packs.h"
#include "scene_data.h"
#include "shared_types.h"

/* ---- shoot.cl: form factors and the progressive solve's shots ---- */

/* counts[row * (patchCount + 2) + column] += 1 for every ray. */
#define RAD_SHOOT_ARGS(X) X(IN, RaySource, sources) X(VALUE, rad_uint, sourceCount) X(VALUE, rad_uint, rayCount) X(VALUE, rad_uint, patchCount) X(OUT, rad_uint, counts)
#define RAD_SHOOT_KERNEL(X) RAD_SCENE_ARGS(X) RAD_SHOOT_ARGS(X)

#define RAD_SHOOT_POWER_ARGS(X) X(IN, RaySource, sources) X(VALUE, rad_uint, sourceCount) X(VALUE, rad_uint, rayCount) X(IN, Shooter, shooters) X(OUT, rad_uint, power) X(IN, ElementNode, elements) X(VALUE, rad_uint, elementCount) X(IN, rad_uint, elementStart) X(IN, rad_uint, elementCdf) X(IN, rad_float4, frames) X(VALUE, rad_uint, takers) X(VALUE, rad_uint, sets) X(VALUE, rad_uint, columns) X(OUT, rad_uint, next) X(OUT, rad_uint, touched)
#define RAD_SHOOT_POWER_KERNEL(X) RAD_SCENE_ARGS(X) RAD_SHOOT_POWER_ARGS(X)

#define RAD_LIGHT_CAUSTICS_ARGS(X) X(IN, rad_float4, rays) X(VALUE, rad_uint, rayCount) X(IN, ElementNode, elements) X(VALUE, rad_uint, elementCount) X(VALUE, rad_uint, key) X(OUT, rad_uint, power)
#define RAD_LIGHT_CAUSTICS_KERNEL(X) RAD_SCENE_ARGS(X) RAD_LIGHT_CAUSTICS_ARGS(X)

/* ---- progressive.cl: the progressive solve's bookkeeping (no scene) ---- */

#define RAD_PREPARE_SHOOTERS_ARGS(X) X(IN, Shooter, shooters) X(VALUE, rad_uint, shooterCount) X(IN, rad_uint, elementStart) X(OUT, rad_float4, incident) X(IN, rad_float4, frames) X(OUT, rad_uint, ends)

#define RAD_TAKE_SHOTS_ARGS(X) X(IN, Shooter, shooters) X(VALUE, rad_uint, shooterCount) X(OUT, rad_float4, unshot)

#define RAD_GATHER_ARGS(X) X(OUT, rad_uint, power) X(VALUE, float, quantum) X(IN, rad_float4, reflectance) X(OUT, rad_float4, incident) X(OUT, rad_float4, unshot) X(IN, rad_uint, elementStart) X(VALUE, rad_uint, patchCount) X(VALUE, rad_uint, elementCount) X(VALUE, rad_uint, workItems) X(OUT, UnshotPartial, partials) X(OUT, rad_float4, lost) X(IN, float, patchArea) X(VALUE, rad_float4, overshoot) X(VALUE, rad_uint, sets) X(VALUE, rad_uint, columns) X(OUT, rad_float4, caustic) X(IN, rad_uint, clusterStart) X(IN, rad_uint, clusterMembers) X(VALUE, rad_uint, clusterCount) X(IN, rad_uint, touched)

#define RAD_MEMBER_POWERS_ARGS(X) X(IN, rad_uint, patches) X(VALUE, rad_uint, patchCount) X(IN, rad_float4, reflectance) X(IN, rad_float4, unshot) X(IN, float, patchArea) X(VALUE, rad_float4, overshoot) X(OUT, rad_float4, powers)

/* ---- gather.cl and hemicube.cl: rows of the patch matrix ---- */

#define RAD_GATHER_ROWS_ARGS(X) X(IN, rad_uint, shooters) X(VALUE, rad_uint, shooterCount) X(VALUE, rad_uint, shadowRays) X(VALUE, rad_uint, seed) X(VALUE, rad_uint, patchCount) X(OUT, rad_uint, rows)
#define RAD_GATHER_ROWS_KERNEL(X) RAD_SCENE_ARGS(X) RAD_GATHER_ROWS_ARGS(X)

#define RAD_HEMICUBE_ROWS_ARGS(X) X(IN, rad_uint, shooters) X(VALUE, rad_uint, shooterCount) X(VALUE, rad_uint, resolution) X(VALUE, rad_uint, jitterSeed) X(VALUE, rad_uint, patchCount) X(OUT, rad_uint, rows)
#define RAD_HEMICUBE_ROWS_KERNEL(X) RAD_SCENE_ARGS(X) RAD_HEMICUBE_ROWS_ARGS(X)

/* Kernels launched over elements (host/device/element_records.h: launchOverElements) take
 * `first` and `elementCount` among their own parameters; in their body,
 *   RAD_ELEMENT_OF_WORK_ITEM(e);
 * names work item i's element e = first + i, and returns for a work item past the last. */
#define RAD_ELEMENT_OF_WORK_ITEM(e)            \
    const uint e = first + get_global_id(0); \
    if (e >= elementCount) return

/* ---- direct_light.cl: light the solvers do not shoot, over elements ---- */

#define RAD_PUNCTUAL_DIRECT_ARGS(X) X(IN, DirectLightElement, elements) X(VALUE, rad_uint, first) X(VALUE, rad_uint, elementCount) X(VALUE, rad_uint, n) X(OUT, rad_float4, out)
#define RAD_PUNCTUAL_DIRECT_KERNEL(X) RAD_SCENE_ARGS(X) RAD_PUNCTUAL_DIRECT_ARGS(X)

#define RAD_ENVIRONMENT_DIRECT_ARGS(X) X(IN, DirectLightElement, elements) X(VALUE, rad_uint, first) X(VALUE, rad_uint, elementCount) X(IN, rad_uint, raysOf) X(VALUE, rad_uint, key) X(OUT, rad_float4, out)
#define RAD_ENVIRONMENT_DIRECT_KERNEL(X) RAD_SCENE_ARGS(X) RAD_ENVIRONMENT_DIRECT_ARGS(X)

/* ---- refine.cl: how direct light varies across elements ---- */

#define RAD_DIRECT_VARIATION_ARGS(X) X(IN, LiftedElement, elements) X(VALUE, rad_uint, first) X(VALUE, rad_uint, elementCount) X(IN, rad_uint, shooters) X(IN, float, exitance) X(VALUE, rad_uint, shooterCount) X(VALUE, rad_uint, rays) X(VALUE, rad_uint, seed) X(VALUE, float, sourceScale) X(OUT, rad_float4, out)
#define RAD_DIRECT_VARIATION_KERNEL(X) RAD_SCENE_ARGS(X) RAD_DIRECT_VARIATION_ARGS(X)

/* ---- the camera pass, the lightmap and the path tracer ---- */

/* The radiosity solution as a path reads it (view_path.h): the element quadtrees, each element's
 * vertices, the light arriving at each element (its mean over the element), and at the vertices
 * its indirect part (direct mode) and the part that came by way of mirrors and glass
 * (caustics != 0). */
#define RAD_VIEW_SOLUTION_ARGS(X) X(IN, ElementNode, elements) X(IN, rad_uint4, corners) X(IN, rad_float4, elementIrradiance) X(IN, rad_float4, vertexIndirect) X(IN, rad_float4, vertexCaustic) X(VALUE, rad_uint, caustics)

#define RAD_RENDER_ARGS(X) X(IN, ElementNode, elements) X(IN, rad_uint4, corners) X(IN, rad_float4, vertexRadiance) X(IN, rad_float4, vertexIrradiance) X(VALUE, rad_uint, showTextures) X(VALUE, CameraRays, camera) X(VALUE, rad_uint, width) X(VALUE, rad_uint, height) X(VALUE, rad_uint, samplesAcross) X(VALUE, rad_uint, samplesDown) X(VALUE, rad_uint, wireframe) X(OUT, rad_float4, image)
#define RAD_RENDER_KERNEL(X) RAD_SCENE_ARGS(X) RAD_RENDER_ARGS(X)

#define RAD_VIEW_PASS_ARGS(X) X(VALUE, CameraRays, camera) X(VALUE, rad_uint, width) X(VALUE, rad_uint, height) X(VALUE, rad_uint, firstSample) X(VALUE, rad_uint, sampleCount) X(VALUE, rad_uint, mode) X(VALUE, rad_uint, seed) X(VALUE, float, near) X(OUT, rad_float4, sums) X(OUT, rad_uint, rays)
#define RAD_VIEW_PASS_KERNEL(X) RAD_SCENE_ARGS(X) RAD_VIEW_SOLUTION_ARGS(X) RAD_VIEW_PASS_ARGS(X)

#define RAD_ELEMENT_INDIRECT_ARGS(X) X(IN, DirectLightElement, layout) X(VALUE, rad_uint, first) X(VALUE, rad_uint, elementCount) X(VALUE, rad_uint, rays) X(VALUE, rad_uint, seed) X(OUT, rad_float4, out)
#define RAD_ELEMENT_INDIRECT_KERNEL(X) RAD_SCENE_ARGS(X) RAD_VIEW_SOLUTION_ARGS(X) RAD_ELEMENT_INDIRECT_ARGS(X)

#define RAD_LIGHTMAP_TEXELS_ARGS(X) X(IN, rad_float4, faceCorners) X(IN, rad_uint, pieceEnds) X(IN, TexelPiece, pieces) X(IN, TexelAnchor, anchors) X(IN, rad_uint, chartOfFace) X(IN, rad_uint, texelKeys) X(VALUE, rad_uint, texelCount) X(VALUE, rad_uint, firstSample) X(VALUE, rad_uint, sampleCount) X(VALUE, rad_uint, mode) X(VALUE, rad_uint, seed) X(VALUE, float, near) X(OUT, rad_uint, enclosure) X(OUT, rad_float4, irradiance) X(OUT, rad_float4, radiance) X(OUT, rad_uint, rays)
#define RAD_LIGHTMAP_TEXELS_KERNEL(X) RAD_SCENE_ARGS(X) RAD_VIEW_SOLUTION_ARGS(X) RAD_LIGHTMAP_TEXELS_ARGS(X)

#define RAD_PATHTRACE_ARGS(X) X(VALUE, rad_uint, lightSampling) X(VALUE, CameraRays, camera) X(VALUE, rad_uint, width) X(VALUE, rad_uint, height) X(VALUE, rad_uint, firstSample) X(VALUE, rad_uint, sampleCount) X(VALUE, rad_uint, maxBounces) X(VALUE, rad_uint, seed) X(OUT, rad_float4, sums) X(OUT, rad_uint, rays)
#define RAD_PATHTRACE_KERNEL(X) RAD_SCENE_ARGS(X) RAD_PATHTRACE_ARGS(X)

/* ---- probes.cl: the kernels' building blocks, for the tests ---- */

#define RAD_PROBE_FIXED_PART_ARGS(X) X(IN, rad_ulong, amounts) X(IN, float, fractions) X(OUT, rad_ulong, parts) X(VALUE, rad_uint, count)

#define RAD_PROBE_PICK_ARGS(X) X(IN, rad_uint, table) X(VALUE, rad_uint, shares) X(IN, rad_uint, xs) X(OUT, rad_uint, picks) X(OUT, rad_uint, guided) X(VALUE, rad_uint, count)

#define RAD_PROBE_GRID_CELL_ARGS(X) X(VALUE, rad_uint, n) X(IN, rad_float2, barycentrics) X(OUT, rad_uint, cells) X(VALUE, rad_uint, count)

#define RAD_PROBE_LOCATE_ELEMENT_ARGS(X) X(IN, ElementNode, nodes) X(IN, rad_uint, patches) X(IN, rad_float4, weights) X(OUT, rad_uint, elements) X(OUT, rad_float4, inElement) X(VALUE, rad_uint, count)

#define RAD_PROBE_TRACE_ARGS(X) X(IN, rad_float4, origins) X(IN, rad_float4, directions) X(OUT, rad_int, hitFaces) X(OUT, rad_float4, hits) X(VALUE, rad_uint, count)
#define RAD_PROBE_TRACE_KERNEL(X) RAD_SCENE_ARGS(X) RAD_PROBE_TRACE_ARGS(X)
#define RAD_PROBE_SHAFT_ARGS(X) X(IN, rad_float4, corners) X(VALUE, float, margin) X(OUT, rad_int, blocked) X(VALUE, rad_uint, count)
#define RAD_PROBE_SHAFT_KERNEL(X) RAD_SCENE_ARGS(X) RAD_PROBE_SHAFT_ARGS(X)
#define RAD_PROBE_LIGHTS_ARGS(X) X(OUT, rad_uint, counts)
#define RAD_PROBE_LIGHTS_KERNEL(X) RAD_SCENE_ARGS(X) RAD_PROBE_LIGHTS_ARGS(X)

#define RAD_PROBE_SAMPLES_ARGS(X) X(VALUE, rad_uint, key) X(OUT, rad_uint4, samples) X(VALUE, rad_uint, count)

#define RAD_PROBE_MAPS_ARGS(X) X(IN, rad_float2, u) X(OUT, rad_float2, disk) X(OUT, rad_float4, direction) X(OUT, rad_float2, barycentrics) X(OUT, rad_float2, sinCos) X(VALUE, rad_uint, count)

#define RAD_PROBE_ENVIRONMENT_ARGS(X) X(VALUE, EnvironmentInfo, info) X(IN, rad_float4, texels) X(IN, rad_uint, rows) X(IN, rad_uint, columns) X(IN, rad_float4, directions) X(IN, rad_uint2, draws) X(OUT, rad_float4, mapped) X(OUT, rad_float4, radiance) X(OUT, rad_float4, drawn) X(VALUE, rad_uint, count)

#define RAD_PROBE_GLOSSY_ARGS(X) X(VALUE, rad_float4, dir) X(VALUE, rad_float4, face) X(VALUE, float, alpha) X(IN, rad_float2, u) X(OUT, rad_float4, drawn) X(OUT, rad_float2, lobe) X(OUT, float, albedo) X(VALUE, rad_uint, count)

#endif
