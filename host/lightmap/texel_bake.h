#pragma once
// The lightmap's texels: per texel, the irradiance E over its footprint on the
// surface, on the anchor's side of any contact (kernels/lightmap.cl says how): direct light by
// light sampling at texel resolution, sharp and soft shadows alike, plus the solution's indirect
// light interpolated or gathered, as the camera pass finds them; and the radiance a viewer would
// see there, Le + rho E / pi. A face's front is baked; a double-sided face's chart is baked on
// the side that received more light in the solution (a viewer shows it on both sides). Texels
// holding no surface, or none of whose samples counted, stay empty (area 0) for
// lightmap/texel_fill.h to fill.
//
// A texel's samples are keyed by its index in the whole lightmap, and the launches depend only
// on the layout and the sample count, so the result depends on the seed alone, never on
// threads, work-group sizes or the order of the work.

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "lightmap/lightmap_layout.h"
#include "prepared/prepared_scene.h"
#include "render/view_pass.h"
#include "render/view_path_inputs.h"

namespace rad {

struct LightmapBakeOptions {
    std::uint32_t samples = 64;                 // per texel
    RenderMode mode = RenderMode::finalGather;  // direct or finalGather (render/view_pass.h)
    std::uint32_t seed = 1;
    double nearPatches = 4.0;                    // as ViewPassOptions
    std::uint32_t indirectRaysPerElement = 256;  // direct mode, as ViewPassOptions
};

// One page, row 0 at the top, texel (x, y) at y * size + x.
struct LightmapPage {
    std::vector<glm::vec3> irradiance;  // E, W / m^2
    std::vector<glm::vec3> radiance;    // Le + rho E / pi, W / m^2 / sr
    std::vector<float> variance;        // of E's luminance, the mean's (samples' spread / n)
    std::vector<double> area;           // the surface the texel holds, m^2; 0: empty
};

struct BakedLightmap {
    std::uint32_t size = 0;  // texels per side of each page
    std::vector<LightmapPage> pages;
    std::uint32_t samples = 0;       // per texel
    std::uint64_t texels = 0;        // holding surface, over all pages (baked, or empty: none counted)
    std::uint64_t sharedTexels = 0;  // of them, holding parts of two or more charts (each keeps its anchor's)
    std::uint64_t backSides = 0;     // double-sided faces baked on their back
    std::uint64_t rays = 0;
};

// About the host memory a bake of `layout` takes at its peak (bytes): every page's values, and one
// page's footprints and gutter fill at a time.
std::uint64_t lightmapHostBytes(const LightmapLayout& layout);

BakedLightmap bakeLightmap(const PreparedScene& scene, const ViewPathSolution& solution, const LightmapLayout& layout,
                           const LightmapBakeOptions& options);

// The same from the solution already on the device (render/view_path_inputs.h), which the camera
// pass may share; it holds the indirect light per element where options.mode is direct.
BakedLightmap bakeLightmap(const PreparedScene& scene, const ViewPathSolution& solution, const ViewPathInputs& inputs,
                           const LightmapLayout& layout, const LightmapBakeOptions& options);

}  // namespace rad
