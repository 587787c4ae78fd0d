#include "device/device_elements.h"

#include <algorithm>
#include <vector>

#include "util/fnv.h"

namespace rad {

namespace {

std::vector<rad_float4> frameList(const ElementMesh& elements) {
    std::vector<rad_float4> list(std::max<std::size_t>(1, elements.elements().size()), rad_float4{{0, 0, 1, 0}});
    for (std::size_t e = 0; e < elements.elements().size(); ++e) {
        const ElementFrame& f = elements.elements()[e].frame;
        list[e] = {{f.s, f.t, f.scale, 0.0f}};
    }
    return list;
}

}  // namespace

std::uint64_t DeviceElements::fingerprint(const ElementMesh& elements) {
    const std::vector<rad_float4> frames = frameList(elements);
    Fnv1a hash;
    hash.add(frames.data(), frames.size() * sizeof(rad_float4));
    hash.add(elements.nodes().data(), elements.nodes().size() * sizeof(ElementNode));
    hash.add(elements.elementStart().data(), elements.elementStart().size() * sizeof(rad_uint));
    return hash.value();
}

DeviceElements::DeviceElements(ComputeContext& compute, const ElementMesh& elements)
    : elementCount(static_cast<std::uint32_t>(elements.elements().size())), contents(fingerprint(elements)) {
    const std::vector<rad_float4> frameList = rad::frameList(elements);
    frames = DeviceArray<rad_float4>::upload(compute, frameList, "element frames");
    nodes = DeviceArray<ElementNode>::upload(compute, elements.nodes(), "element trees");
    elementStart = DeviceArray<rad_uint>::upload(compute, elements.elementStart(), "element starts");
}

}  // namespace rad
