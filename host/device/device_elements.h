#pragma once
// The element quadtrees on the device (mesh/elements.h): what the power-delivering rays, the
// solver's kernels and the camera pass read to find and address elements. One copy per element
// mesh, which DeviceScene::elements hands to all who read it.

#include <cstdint>

#include "cl/device_array.h"
#include "cl/kernel_pack.h"
#include "mesh/elements.h"
#include "shared_types.h"

namespace rad {

class DeviceElements {
public:
    DeviceElements(ComputeContext& compute, const ElementMesh& elements);

    // What the arrays hold, as a hash of their bytes: equal for equal meshes.
    static std::uint64_t fingerprint(const ElementMesh& elements);

    DeviceArray<ElementNode> nodes;
    DeviceArray<rad_uint> elementStart;
    DeviceArray<rad_float4> frames;  // per element: (s, t, scale, 0), its ElementFrame in its patch
    std::uint32_t elementCount = 0;
    std::uint64_t contents = 0;  // fingerprint() of the mesh uploaded
};

}  // namespace rad
