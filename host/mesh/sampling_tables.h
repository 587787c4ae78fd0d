#pragma once
// Where rays start: every patch as a triangle rays can leave from, then each surface side's
// faces with the area tables that spread a surface's rays over it in proportion to area. Built
// on the host from the mesh; uploaded with the scene (device/device_scene.h) and read by
// kernels/ray_source.h.

#include <cstdint>
#include <vector>

#include "mesh/mesh.h"
#include "shared_types.h"

namespace rad {

struct TriangleRun {
    std::uint32_t first = 0, count = 0;
    std::uint32_t guide = 0;  // where the guide to its area table starts in cdf (count > 1)
};

// triangles[p] is patch p; after the patches come the faces of each surface side, oriented to
// that side, so a surface is sampled by face (its patches do not matter and a 2-D stratified
// sample stays stratified on each face). cdf[k] is the end of triangle k's share of 2^32 within
// its run, in proportion to area (kernels/ray_source.h); after the triangles' entries, each
// run's guide to its table (util/shares.h: shareGuide), which a ray's search starts from.
struct SamplingTables {
    std::vector<SampleTriangle> triangles;
    std::vector<std::uint32_t> cdf;
    std::vector<TriangleRun> surfaceRuns;  // one per Mesh::surfaces entry
};

SamplingTables buildSamplingTables(const Mesh& mesh);

// How far ray origins keep off a triangle whose largest coordinate (in magnitude) is
// `largest`: about 16 ulps of it, more than the rounding of a sampled point, far less than
// any gap a scene models on purpose.
inline float originLift(float largest) {
    return largest * 0x1p-19f;
}

}  // namespace rad
