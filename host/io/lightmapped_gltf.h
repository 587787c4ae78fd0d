#pragma once
// lightmapped.glb (issue 16, part 4): the input scene's meshes as the file had them (positions,
// normals, TEXCOORD_0, triangles; a vertex is split only where it sits at two places of the
// lightmap, a chart's edge), plus the lightmap's UVs as TEXCOORD_1 (and as TEXCOORD_0 where the
// scene has none, as glTF numbers UV sets from 0) and the lightmap wired so
// that any glTF viewer shows the baked light: each material becomes black (baseColorFactor 0,
// metallic 0, roughness 1) with the lightmap page as its emissiveTexture on TEXCOORD_1, the
// page holding the radiance a viewer sees (Le + rho E / pi) over `strength`, sRGB-encoded, and
// `strength` as the emissive factor where it is at most 1, else as
// KHR_materials_emissive_strength (the factor 1), so the viewer shows the radiance itself.
// Radiance above `strength` (emitters, mostly) clips. The sampler is bilinear without mipmaps
// (the charts' 2-texel gutters would not keep mip levels apart). Engines that apply a lightmap to their
// own materials read TEXCOORD_1 and the irradiance pages (lightmap.exr) instead.

#include <string>
#include <vector>

#include "lightmap/lightmap_layout.h"
#include "mesh/mesh.h"
#include "render/image.h"
#include "scene/scene.h"

namespace rad {

void writeLightmappedGltf(const std::string& path, const Scene& scene, const Mesh& mesh, const LightmapLayout& layout,
                          const std::vector<Image>& radiancePages, double strength);

}  // namespace rad
