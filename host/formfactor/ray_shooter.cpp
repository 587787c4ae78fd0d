#include "formfactor/ray_shooter.h"

namespace rad {

RayShooter::RayShooter(ComputeContext& compute, const DeviceScene& scene)
    : compute_(compute),
      scene_(scene),
      count_(scene.kernel<ShootArgs>("shoot.cl", "shoot")),
      power_(scene.kernel<ShootPowerArgs>("shoot.cl", "shoot_power")),
      next_(DeviceArray<rad_uint>::allocate(compute, 1, "next ray to take")) {}

void RayShooter::uploadSources(const Launch& launch) {
    if (launch.sources.size() > sources_.size())
        sources_ = DeviceArray<RaySource>::allocate(compute_, launch.sources.size(), "ray sources", DeviceAccess::read);
    // Not blocking: the caller keeps the launches until the queue has finished them. The queue
    // runs in order, so this write waits for the previous launch, which read the same array.
    sources_.enqueueWrite(launch.sources);
}

void RayShooter::countHits(const std::vector<Launch>& launches, DeviceArray<rad_uint>& counts) {
    ShootArgs args;
    args.patchCount = scene_.patchCount();
    args.counts = counts;
    for (const Launch& launch : launches) {
        uploadSources(launch);
        args.sources = sources_;
        args.sourceCount = static_cast<rad_uint>(launch.sources.size());
        args.rayCount = static_cast<rad_uint>(launch.rayCount);
        count_.launch(args, launch.rayCount);
    }
}

void RayShooter::deliverPower(const std::vector<Launch>& launches, const DeviceArray<Shooter>& shooters,
                              DeviceArray<rad_uint>& power, const DeviceElements& elements,
                              const DeviceArray<rad_uint>& elementCdf, const CounterLayout& layout,
                              std::uint32_t columns, DeviceArray<rad_uint>& touched) {
    ShootPowerArgs args;
    args.shooters = shooters;
    args.power = power;
    args.elements = elements.nodes;
    args.elementCount = elements.elementCount;
    args.elementStart = elements.elementStart;
    args.elementCdf = elementCdf;
    args.frames = elements.frames;
    args.takers = layout.takers;
    args.sets = layout.sets;
    args.columns = columns;
    args.next = next_;
    args.touched = touched;
    for (const Launch& launch : launches) {
        uploadSources(launch);
        args.sources = sources_;
        args.sourceCount = static_cast<rad_uint>(launch.sources.size());
        args.rayCount = static_cast<rad_uint>(launch.rayCount);
        if (layout.takers > 0) {
            next_.fill(0u);
            power_.launchGroups(args, layout.takers);  // a work group per taker
        } else {
            power_.launch(args, launch.rayCount);
        }
    }
}

}  // namespace rad
