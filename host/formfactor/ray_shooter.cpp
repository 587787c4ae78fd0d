#include "formfactor/ray_shooter.h"

#include "cl/error.h"

namespace rad {

RayShooter::RayShooter(ComputeContext& compute, const DeviceScene& scene) : compute_(compute), scene_(scene) {
    cl::Program& program = compute.program("shoot.cl");
    try {
        count_ = cl::Kernel(program, "shoot");
        power_ = cl::Kernel(program, "shoot_power");
    } catch (const cl::Error& e) {
        throwDeviceError(e, "creating the shoot kernels");
    }
}

void RayShooter::prepare(cl::Kernel& kernel, const Launch& launch) {
    if (launch.sources.size() > sourceCapacity_) {
        sourceCapacity_ = launch.sources.size();
        sources_ = cl::Buffer(compute_.context(), CL_MEM_READ_ONLY, sourceCapacity_ * sizeof(RaySource));
    }
    // Not blocking: the caller keeps the launches until the queue has finished them. The queue
    // runs in order, so this write waits for the previous launch, which read the same buffer.
    compute_.queue().enqueueWriteBuffer(sources_, CL_FALSE, 0, launch.sources.size() * sizeof(RaySource),
                                        launch.sources.data());
    int arg = 0;
    kernel.setArg(arg++, scene_.nodes);
    kernel.setArg(arg++, scene_.blocks);
    kernel.setArg(arg++, scene_.faces);
    kernel.setArg(arg++, scene_.triangles);
    kernel.setArg(arg++, scene_.cdf);
    kernel.setArg(arg++, sources_);
    kernel.setArg(arg++, static_cast<cl_uint>(launch.sources.size()));
    kernel.setArg(arg++, static_cast<cl_uint>(launch.rayCount));
    kernel.setArg(arg++, static_cast<cl_uint>(scene_.patchCount));
}


void RayShooter::countHits(const std::vector<Launch>& launches, cl::Buffer& counts) {
    try {
        for (const Launch& launch : launches) {
            prepare(count_, launch);
            count_.setArg(9, counts);
            compute_.launch(count_, launch.rayCount);
        }
    } catch (const cl::Error& e) {
        throwDeviceError(e, "shooting rays");
    }
}

void RayShooter::deliverPower(const std::vector<Launch>& launches, const cl::Buffer& shooters, cl::Buffer& power) {
    try {
        for (const Launch& launch : launches) {
            prepare(power_, launch);
            power_.setArg(9, shooters);
            power_.setArg(10, power);
            compute_.launch(power_, launch.rayCount);
        }
    } catch (const cl::Error& e) {
        throwDeviceError(e, "shooting rays");
    }
}

}  // namespace rad
