#pragma once
// Runs kernels/shoot.cl: casts the rays of a set of sources and sums, per column, what they
// land on. Columns: one per patch, then "escaped the scene" (patchCount), then "stopped by the
// black back of a single-sided face" (patchCount + 1).

#include <cstdint>
#include <vector>

#include "cl/compute_context.h"
#include "formfactor/counter_layout.h"
#include "formfactor/launch_plan.h"
#include "device/device_elements.h"
#include "device/device_scene.h"
#include "device/kernel_arguments.h"

namespace rad {

class RayShooter {
public:
    RayShooter(ComputeContext& compute, const DeviceScene& scene);

    std::uint32_t columns() const { return scene_.patchCount() + 2; }
    std::uint32_t escapedColumn() const { return scene_.patchCount(); }
    std::uint32_t blackColumn() const { return scene_.patchCount() + 1; }

    // Both enqueue their work and return: `launches` (and `shooters`' contents) must stay alive
    // and unchanged until the queue has finished (a blocking read of the results does that).

    // counts (rows x columns uint32, row = the source's row) += 1 per ray.
    void countHits(const std::vector<Launch>& launches, DeviceArray<rad_uint>& counts);

    // power (`columns` x 3 channels x 64-bit fixed point) += each ray's power, as its
    // row's Shooter says (kernels/shared_types.h), in the column of the element it lands on
    // (elements: escaped; + 1: black back). Where the scene has mirrors or glass, rays go on
    // through them and leave what those absorb with the element they met (kernels/shoot.cl's
    // walk_specular, specular_walk.h). Rays leave a shooter's elements in the proportions
    // of elementCdf (progressive.cl's prepare_shooters). `power` holds `layout.sets` sets of
    // counters one after another, whose sum is the same bits for any layout.
    // `columns`: of each set of counters, elements + 2, or with mirrors or glass in the scene
    // 2 x elements + 2, the last elements for the power that came by way of them. `touched`:
    // the blocks of elements a ray delivered to are set to 1 (kernels/shared_types.h,
    // RAD_TOUCHED_SHIFT).
    void deliverPower(const std::vector<Launch>& launches, const DeviceArray<Shooter>& shooters,
                      DeviceArray<rad_uint>& power, const DeviceElements& elements,
                      const DeviceArray<rad_uint>& elementCdf, const CounterLayout& layout, std::uint32_t columns,
                      DeviceArray<rad_uint>& touched);

    // Rays per launch: large enough to hide launch overhead, small enough to return promptly.
    static constexpr std::uint32_t kMaxRaysPerLaunch = 1u << 21;

private:
    void uploadSources(const Launch& launch);

    ComputeContext& compute_;
    const DeviceScene& scene_;
    DeviceKernel<ShootArgs> count_;
    DeviceKernel<ShootPowerArgs> power_;
    DeviceArray<RaySource> sources_;
    DeviceArray<rad_uint> next_;
};

}  // namespace rad
