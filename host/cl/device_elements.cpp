#include "cl/device_elements.h"

#include <algorithm>
#include <vector>

#include "cl/error.h"

static_assert(sizeof(ElementNode) == 8, "ElementNode must match the kernels' layout");

namespace rad {

DeviceElements::DeviceElements(ComputeContext& compute, const ElementMesh& elements)
    : elementCount(static_cast<std::uint32_t>(elements.elements().size())) {
    const auto& nodeList = elements.nodes();
    const auto& start = elements.elementStart();
    const std::uint64_t nodeBytes = std::max<std::size_t>(1, nodeList.size()) * sizeof(ElementNode);
    const std::uint64_t startBytes = std::max<std::size_t>(1, start.size()) * sizeof(std::uint32_t);
    std::vector<cl_float4> frameList(std::max<std::size_t>(1, elementCount), cl_float4{{0, 0, 1, 0}});
    for (std::size_t e = 0; e < elementCount; ++e) {
        const ElementFrame& f = elements.elements()[e].frame;
        frameList[e] = {{f.s, f.t, f.scale, 0.0f}};
    }
    const std::uint64_t frameBytes = frameList.size() * sizeof(cl_float4);
    reservation = compute.reserve(nodeBytes + startBytes + frameBytes, std::max({nodeBytes, startBytes, frameBytes}),
                                  "the element trees");
    try {
        frames = cl::Buffer(compute.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, frameBytes, frameList.data());
        nodes = cl::Buffer(compute.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, nodeBytes,
                           const_cast<ElementNode*>(nodeList.data()));
        elementStart = cl::Buffer(compute.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, startBytes,
                                  const_cast<std::uint32_t*>(start.data()));
    } catch (const cl::Error& e) {
        throwDeviceError(e, "uploading the element trees");
    }
}

}  // namespace rad
