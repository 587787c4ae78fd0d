#pragma once
// Runs kernels/shoot.cl: casts the rays of a set of sources and counts, per source row, what
// they land on. Row layout: one column per patch, then "escaped the scene", then "stopped by
// the black back of a single-sided face".

#include <cstdint>
#include <vector>

#include "cl/compute_context.h"
#include "cl/device_scene.h"
#include "formfactor/launch_plan.h"

namespace rad {

class RayShooter {
public:
    RayShooter(ComputeContext& compute, const DeviceScene& scene);

    std::uint32_t stride() const { return scene_.patchCount + 2; }
    std::uint32_t escapedColumn() const { return scene_.patchCount; }
    std::uint32_t blackColumn() const { return scene_.patchCount + 1; }

    // Enqueues the launches; counts (rows x stride uint32) accumulate on the device.
    void enqueue(const std::vector<Launch>& launches, cl::Buffer& counts);

    // Rays per launch: large enough to hide launch overhead, small enough to return promptly.
    static constexpr std::uint32_t kMaxRaysPerLaunch = 1u << 21;

private:
    ComputeContext& compute_;
    const DeviceScene& scene_;
    cl::Kernel kernel_;
    cl::Buffer sources_;
    std::size_t sourceCapacity_ = 0;
};

}  // namespace rad
