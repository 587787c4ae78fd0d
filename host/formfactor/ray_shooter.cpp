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

void RayShooter::uploadSources(const Launch& launch) {
    if (launch.sources.size() > sourceCapacity_) {
        sourceCapacity_ = launch.sources.size();
        sources_ = cl::Buffer(compute_.context(), CL_MEM_READ_ONLY, sourceCapacity_ * sizeof(RaySource));
    }
    // Not blocking: the caller keeps the launches until the queue has finished them. The queue
    // runs in order, so this write waits for the previous launch, which read the same buffer.
    compute_.queue().enqueueWriteBuffer(sources_, CL_FALSE, 0, launch.sources.size() * sizeof(RaySource),
                                        launch.sources.data());
}

void RayShooter::countHits(const std::vector<Launch>& launches, cl::Buffer& counts) {
    try {
        for (const Launch& launch : launches) {
            uploadSources(launch);
            int arg = 0;
            count_.setArg(arg++, scene_.nodes);
            count_.setArg(arg++, scene_.blocks);
            count_.setArg(arg++, scene_.faces);
            count_.setArg(arg++, scene_.triangles);
            count_.setArg(arg++, scene_.cdf);
            count_.setArg(arg++, sources_);
            count_.setArg(arg++, static_cast<cl_uint>(launch.sources.size()));
            count_.setArg(arg++, static_cast<cl_uint>(launch.rayCount));
            count_.setArg(arg++, static_cast<cl_uint>(scene_.patchCount));
            count_.setArg(arg++, counts);
            compute_.launch(count_, launch.rayCount);
        }
    } catch (const cl::Error& e) {
        throwDeviceError(e, "shooting rays");
    }
}

void RayShooter::deliverPower(const std::vector<Launch>& launches, const cl::Buffer& shooters, cl::Buffer& power,
                              const DeviceElements& elements, const cl::Buffer& elementCdf) {
    try {
        for (const Launch& launch : launches) {
            uploadSources(launch);
            int arg = 0;
            power_.setArg(arg++, scene_.nodes);
            power_.setArg(arg++, scene_.blocks);
            power_.setArg(arg++, scene_.faces);
            power_.setArg(arg++, scene_.triangles);
            power_.setArg(arg++, sources_);
            power_.setArg(arg++, static_cast<cl_uint>(launch.sources.size()));
            power_.setArg(arg++, static_cast<cl_uint>(launch.rayCount));
            power_.setArg(arg++, shooters);
            power_.setArg(arg++, power);
            power_.setArg(arg++, elements.nodes);
            power_.setArg(arg++, static_cast<cl_uint>(elements.elementCount));
            power_.setArg(arg++, elements.elementStart);
            power_.setArg(arg++, elementCdf);
            power_.setArg(arg++, elements.frames);
            compute_.launch(power_, launch.rayCount);
        }
    } catch (const cl::Error& e) {
        throwDeviceError(e, "shooting rays");
    }
}

}  // namespace rad
