#pragma once
// The element quadtrees on the device (mesh/elements.h): what the power-delivering rays, the
// solver's kernels and the camera pass read to find and address elements.

#include <cstdint>

#include "cl/device_array.h"
#include "cl/kernel_pack.h"
#include "mesh/elements.h"
#include "shared_types.h"

namespace rad {

class DeviceElements {
public:
    DeviceElements(ComputeContext& compute, const ElementMesh& elements);

    DeviceArray<ElementNode> nodes;
    DeviceArray<rad_uint> elementStart;
    DeviceArray<rad_float4> frames;  // per element: (s, t, scale, 0), its ElementFrame in its patch
    std::uint32_t elementCount = 0;
};

}  // namespace rad
