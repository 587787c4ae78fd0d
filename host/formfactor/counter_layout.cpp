#include "formfactor/counter_layout.h"

#include <algorithm>

#include "cl/compute_context.h"

namespace rad {

CounterLayout CounterLayout::forDevice(const ComputeContext& compute, std::uint64_t bytesPerSet,
                                       std::uint64_t budgetBytes) {
    const DeviceDescription& device = compute.description();
    CounterLayout layout;
    // PoCL only, where it was measured and tested. Not on Mesa's rusticl (llvmpipe): it ends
    // every loop of a work item after 65,535 iterations in all (LP_MAX_TGSI_LOOP_ITERATIONS),
    // and a taker loops over hundreds of thousands of rays, so rays would go uncast.
    if (device.type == "cpu" && device.platform == "Portable Computing Language") {
        layout.takers = std::max(1u, device.computeUnits);
        const std::uint64_t available =
            device.globalMemory > compute.reservedBytes() ? device.globalMemory - compute.reservedBytes() : 0;
        const std::uint64_t budget = std::min({budgetBytes, device.maxAllocation, available / 4});
        const std::uint64_t fit = std::max<std::uint64_t>(1, budget / std::max<std::uint64_t>(1, bytesPerSet));
        layout.sets = static_cast<std::uint32_t>(std::min<std::uint64_t>(layout.takers, fit));
    }
    return layout;
}

}  // namespace rad
