#include "formfactor/ray_shooter.h"

#include "cl/error.h"

namespace rad {

RayShooter::RayShooter(ComputeContext& compute, const DeviceScene& scene) : compute_(compute), scene_(scene) {
    cl::Program& program = compute.program("shoot.cl");
    try {
        kernel_ = cl::Kernel(program, "shoot");
    } catch (const cl::Error& e) {
        throwDeviceError(e, "creating the shoot kernel");
    }
}

void RayShooter::enqueue(const std::vector<Launch>& launches, cl::Buffer& counts) {
    const std::size_t group = compute_.workGroupSize();
    try {
        for (const Launch& launch : launches) {
            if (launch.sources.size() > sourceCapacity_) {
                sourceCapacity_ = launch.sources.size();
                sources_ = cl::Buffer(compute_.context(), CL_MEM_READ_ONLY, sourceCapacity_ * sizeof(RaySource));
            }
            compute_.queue().enqueueWriteBuffer(sources_, CL_TRUE, 0, launch.sources.size() * sizeof(RaySource),
                                                launch.sources.data());
            int arg = 0;
            kernel_.setArg(arg++, scene_.nodes);
            kernel_.setArg(arg++, scene_.blocks);
            kernel_.setArg(arg++, scene_.faces);
            kernel_.setArg(arg++, scene_.triangles);
            kernel_.setArg(arg++, scene_.cdf);
            kernel_.setArg(arg++, sources_);
            kernel_.setArg(arg++, static_cast<cl_uint>(launch.sources.size()));
            kernel_.setArg(arg++, static_cast<cl_uint>(launch.rayCount));
            kernel_.setArg(arg++, counts);
            kernel_.setArg(arg++, static_cast<cl_uint>(stride()));
            const std::size_t global = (launch.rayCount + group - 1) / group * group;
            compute_.queue().enqueueNDRangeKernel(kernel_, cl::NullRange, cl::NDRange(global), cl::NDRange(group));
        }
    } catch (const cl::Error& e) {
        throwDeviceError(e, "shooting rays");
    }
}

}  // namespace rad
