#include "device/device_elements.h"

#include <algorithm>
#include <vector>

namespace rad {

DeviceElements::DeviceElements(ComputeContext& compute, const ElementMesh& elements)
    : elementCount(static_cast<std::uint32_t>(elements.elements().size())) {
    std::vector<rad_float4> frameList(std::max<std::size_t>(1, elementCount), rad_float4{{0, 0, 1, 0}});
    for (std::size_t e = 0; e < elementCount; ++e) {
        const ElementFrame& f = elements.elements()[e].frame;
        frameList[e] = {{f.s, f.t, f.scale, 0.0f}};
    }
    frames = DeviceArray<rad_float4>::upload(compute, frameList, "element frames");
    nodes = DeviceArray<ElementNode>::upload(compute, elements.nodes(), "element trees");
    elementStart = DeviceArray<rad_uint>::upload(compute, elements.elementStart(), "element starts");
}

}  // namespace rad
