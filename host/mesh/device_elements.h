#pragma once
// The element quadtrees on the device (mesh/elements.h): what the power-delivering rays, the
// solver's kernels and the camera pass read to find and address elements.

#include <cstdint>

#include "cl/compute_context.h"
#include "mesh/elements.h"

namespace rad {

class DeviceElements {
public:
    DeviceElements(ComputeContext& compute, const ElementMesh& elements);

    cl::Buffer nodes, elementStart;
    cl::Buffer frames;  // per element: (s, t, scale, 0), its ElementFrame in its patch
    std::uint32_t elementCount = 0;
    MemoryReservation reservation;
};

}  // namespace rad
