#include "mesh/device_elements.h"

#include <algorithm>
#include <vector>

#include "cl/buffers.h"

static_assert(sizeof(ElementNode) == 8, "ElementNode must match the kernels' layout");

namespace rad {

DeviceElements::DeviceElements(ComputeContext& compute, const ElementMesh& elements)
    : elementCount(static_cast<std::uint32_t>(elements.elements().size())) {
    std::vector<cl_float4> frameList(std::max<std::size_t>(1, elementCount), cl_float4{{0, 0, 1, 0}});
    for (std::size_t e = 0; e < elementCount; ++e) {
        const ElementFrame& f = elements.elements()[e].frame;
        frameList[e] = {{f.s, f.t, f.scale, 0.0f}};
    }
    const std::uint64_t nodeBytes = bufferBytes<ElementNode>(elements.nodes().size());
    const std::uint64_t startBytes = bufferBytes<std::uint32_t>(elements.elementStart().size());
    const std::uint64_t frameBytes = bufferBytes<cl_float4>(frameList.size());
    reservation = compute.reserve(nodeBytes + startBytes + frameBytes, std::max({nodeBytes, startBytes, frameBytes}),
                                  "the element trees");
    frames = uploadBuffer(compute, frameList, "element frames");
    nodes = uploadBuffer(compute, elements.nodes(), "element trees");
    elementStart = uploadBuffer(compute, elements.elementStart(), "element starts");
}

}  // namespace rad
