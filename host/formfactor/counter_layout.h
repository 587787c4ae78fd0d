#pragma once
// How the progressive solver's rays add into the delivered-power counters (kernels/shoot.cl's
// shoot_power): into one set, a work item per ray, or on PoCL's CPU device into a set per thread.

#include <cstdint>

namespace rad {

class ComputeContext;

struct CounterLayout {
    // 0: one work item per ray (GPUs, and every device but PoCL's CPU device). Otherwise that
    // many work groups take rays 64 at a time until none are left (PoCL: one per thread).
    std::uint32_t takers = 0;
    std::uint32_t sets = 1;  // counter sets; taker k adds into set k mod sets

    // At least one set (a layout asked for with none gets one).
    CounterLayout normalised() const { return {takers, sets > 0 ? sets : 1}; }

    // For `compute`'s device: on PoCL's CPU device, a taker per compute unit (per thread) and
    // as many sets, as far as they fit in `budgetBytes`, in the device's largest allocation and
    // in a quarter of its free memory (one at least): threads adding into one set pass its cache
    // lines between cores on nearly every ray (docs/results.md). Otherwise one set, a work item
    // per ray.
    static CounterLayout forDevice(const ComputeContext& compute, std::uint64_t bytesPerSet,
                                   std::uint64_t budgetBytes = std::uint64_t{256} << 20);
};

}  // namespace rad
