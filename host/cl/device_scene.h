#pragma once
// The scene on the device: the BVH, the faces' patch grids, and the triangles rays start from
// with the area tables that spread rays over a surface. Uploaded once, read by every kernel
// that traces rays.

#include <cstdint>
#include <vector>

#include "bvh/wide_bvh.h"
#include "cl/compute_context.h"
#include "mesh/mesh.h"

namespace rad {

struct TriangleRun {
    std::uint32_t first = 0, count = 0;
};

// What rays start from. triangles[p] is patch p; after the patches come the faces of each
// surface side, oriented to that side, so a surface is sampled by face (its patches do not
// matter and a 2-D stratified sample stays stratified on each face). cdf[k] is the end of
// triangle k's share of 2^32 within its run, in proportion to area (kernels/ray_source.h).
struct SamplingTables {
    std::vector<SampleTriangle> triangles;
    std::vector<std::uint32_t> cdf;
    std::vector<TriangleRun> surfaceRuns;  // one per Mesh::surfaces entry
};

SamplingTables buildSamplingTables(const Mesh& mesh);

class DeviceScene {
public:
    DeviceScene(ComputeContext& compute, const Mesh& mesh, const WideBvh& bvh);

    cl::Buffer nodes, blocks, faces, triangles, cdf;
    std::vector<TriangleRun> surfaceRuns;
    std::uint32_t patchCount = 0;
    std::uint64_t bytes = 0;  // device memory these buffers take
    MemoryReservation reservation;
};

}  // namespace rad
