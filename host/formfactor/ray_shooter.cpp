#include "formfactor/ray_shooter.h"

#include "cl/buffers.h"
#include "cl/error.h"

namespace rad {

RayShooter::RayShooter(ComputeContext& compute, const DeviceScene& scene) : compute_(compute), scene_(scene) {
    cl::Program& program = scene.program(compute, "shoot.cl");
    count_ = scene.kernel(program, "shoot");
    power_ = scene.kernel(program, "shoot_power");
    next_ = allocateBuffer<cl_uint>(compute, 1, "the next ray to take", CL_MEM_READ_WRITE);
}

void RayShooter::uploadSources(const Launch& launch) {
    if (launch.sources.size() > sourceCapacity_) {
        sourceCapacity_ = launch.sources.size();
        sources_ = allocateBuffer<RaySource>(compute_, sourceCapacity_, "ray sources", CL_MEM_READ_ONLY);
    }
    // Not blocking: the caller keeps the launches until the queue has finished them. The queue
    // runs in order, so this write waits for the previous launch, which read the same buffer.
    enqueueWrite(compute_, sources_, launch.sources);
}

void RayShooter::countHits(const std::vector<Launch>& launches, cl::Buffer& counts) {
    try {
        for (const Launch& launch : launches) {
            uploadSources(launch);
            setKernelArgs(count_, DeviceScene::kArguments, sources_, static_cast<cl_uint>(launch.sources.size()),
                          static_cast<cl_uint>(launch.rayCount), static_cast<cl_uint>(scene_.patchCount), counts);
            compute_.launch(count_, launch.rayCount);
        }
    } catch (const cl::Error& e) {
        throwDeviceError(e, "shooting rays");
    }
}

void RayShooter::deliverPower(const std::vector<Launch>& launches, const cl::Buffer& shooters, cl::Buffer& power,
                              const DeviceElements& elements, const cl::Buffer& elementCdf, const CounterLayout& layout,
                              std::uint32_t columns) {
    try {
        for (const Launch& launch : launches) {
            uploadSources(launch);
            setKernelArgs(power_, DeviceScene::kArguments, sources_, static_cast<cl_uint>(launch.sources.size()),
                          static_cast<cl_uint>(launch.rayCount), shooters, power, elements.nodes,
                          static_cast<cl_uint>(elements.elementCount), elements.elementStart, elementCdf,
                          elements.frames, scene_.lift, static_cast<cl_uint>(layout.takers),
                          static_cast<cl_uint>(layout.sets), static_cast<cl_uint>(columns), next_);
            if (layout.takers > 0) {
                compute_.queue().enqueueFillBuffer(next_, cl_uint{0}, 0, sizeof(cl_uint));
                compute_.launch(power_, std::size_t{layout.takers} * compute_.workGroupSize());  // a group per taker
            } else {
                compute_.launch(power_, launch.rayCount);
            }
        }
    } catch (const cl::Error& e) {
        throwDeviceError(e, "shooting rays");
    }
}

}  // namespace rad
