#include "cl/compute_context.h"

#include <algorithm>

#include "cl/error.h"
#include "cl/kernel_source.h"
#include "util/error.h"

namespace rad {

std::shared_ptr<ComputeContext> ComputeContext::open(const std::string& selector, bool profiling) {
    return std::make_shared<ComputeContext>(chooseDevice(selector), profiling);
}

ComputeContext::ComputeContext(DeviceDescription description, bool profiling)
    : description_(std::move(description)), profiling_(profiling) {
    try {
        context_ = cl::Context(description_.device);
        queue_ = cl::CommandQueue(context_, description_.device, profiling ? CL_QUEUE_PROFILING_ENABLE : 0);
    } catch (const cl::Error& e) {
        throwDeviceError(e, "opening OpenCL device '" + description_.name + "'");
    }
}

std::size_t ComputeContext::workGroupSize() const {
    return workGroupSize_ > 0 ? workGroupSize_ : std::min<std::size_t>(64, description_.maxWorkGroupSize);
}

void ComputeContext::setWorkGroupSize(std::size_t size) {
    if (size == 0 || size > description_.maxWorkGroupSize)
        throw InputError("work-group size " + std::to_string(size) + " is outside 1.." +
                         std::to_string(description_.maxWorkGroupSize) + " on this device");
    workGroupSize_ = size;
}

cl::Program& ComputeContext::program(const std::string& mainFile, const std::string& defines) {
    const std::string key = mainFile + (defines.empty() ? "" : " " + defines);
    auto found = programs_.find(key);
    if (found != programs_.end()) return found->second;
    return programs_.emplace(key, build("kernels/" + mainFile, kernelSource(mainFile), defines)).first->second;
}

cl::Program ComputeContext::build(const std::string& name, const std::string& source, const std::string& defines) {
    // No fast-math: it gains nothing on PoCL and makes INFINITY undefined. Correctly rounded
    // division and square root, where offered, keep results equal across devices.
    std::string options = "-cl-std=CL1.2";
    if (description_.correctlyRoundedDivideSqrt) options += " -cl-fp32-correctly-rounded-divide-sqrt";
    if (!defines.empty()) options += " " + defines;
    cl::Program program;
    try {
        program = cl::Program(context_, source);
    } catch (const cl::Error& e) {
        throwDeviceError(e, "creating the OpenCL program " + name);
    }
    try {
        program.build({description_.device}, options.c_str());
    } catch (const cl::Error& e) {
        std::string log;
        try {
            log = program.getBuildInfo<CL_PROGRAM_BUILD_LOG>(description_.device);
        } catch (const cl::Error&) {
            log = "(no build log)";
        }
        throw DeviceError("building " + name + " for '" + description_.name + "' failed with " + clErrorName(e.err()) +
                          "; compiler log:\n" + log);
    }
    return program;
}

}  // namespace rad

namespace rad {

void ComputeContext::launch(cl::Kernel& kernel, std::size_t items) {
    const std::size_t group = workGroupSize();
    const std::size_t global = (std::max<std::size_t>(items, 1) + group - 1) / group * group;
    if (!profiling_) {
        queue_.enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(global), cl::NDRange(group));
        return;
    }
    cl::Event event;
    queue_.enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(global), cl::NDRange(group), nullptr, &event);
    events_.emplace_back(kernel.getInfo<CL_KERNEL_FUNCTION_NAME>(), event);
}

void ComputeContext::finish() {
    try {
        queue_.finish();
    } catch (const cl::Error& e) {
        throwDeviceError(e, "waiting for the device");
    }
}

std::map<std::string, double> ComputeContext::takeKernelSeconds() {
    std::map<std::string, double> seconds;
    if (!profiling_) return seconds;
    try {
        queue_.finish();
        for (const auto& [name, e] : events_)
            seconds[name] += 1e-9 * static_cast<double>(e.getProfilingInfo<CL_PROFILING_COMMAND_END>() -
                                                        e.getProfilingInfo<CL_PROFILING_COMMAND_START>());
    } catch (const cl::Error& e) {
        throwDeviceError(e, "reading kernel timings");
    }
    events_.clear();
    return seconds;
}

}  // namespace rad

namespace rad {

MemoryReservation& MemoryReservation::operator=(MemoryReservation&& other) noexcept {
    if (this != &other) {
        if (owner_) owner_->reserved_ -= bytes_;
        owner_ = other.owner_;
        bytes_ = other.bytes_;
        other.owner_ = nullptr;
        other.bytes_ = 0;
    }
    return *this;
}

MemoryReservation::~MemoryReservation() {
    if (owner_) owner_->reserved_ -= bytes_;
}

MemoryReservation ComputeContext::reserve(std::uint64_t bytes, std::uint64_t largestBuffer, const std::string& what) {
    auto mib = [](std::uint64_t b) { return std::to_string((b + (1u << 20) - 1) >> 20) + " MiB"; };
    if (largestBuffer > description_.maxAllocation)
        throw DeviceError(what + " need a buffer of " + mib(largestBuffer) + "; '" + description_.name +
                          "' allows at most " + mib(description_.maxAllocation) + " in one buffer");
    if (reserved_ + bytes > description_.globalMemory)
        throw DeviceError(what + " need " + mib(bytes) + " of device memory; '" + description_.name + "' has " +
                          mib(description_.globalMemory) + (reserved_ > 0 ? " with " + mib(reserved_) + " in use" : ""));
    reserved_ += bytes;
    return MemoryReservation(this, bytes);
}

}  // namespace rad
