#pragma once
// One OpenCL device with its context, an in-order queue and the programs built for it.

#include <map>
#include <memory>
#include <string>

#include "cl/device_list.h"
#include "cl/opencl.h"

namespace rad {

class ComputeContext {
public:
    // Opens the device chooseDevice(selector) picks.
    static std::shared_ptr<ComputeContext> open(const std::string& selector);

    explicit ComputeContext(DeviceDescription description);

    const DeviceDescription& description() const { return description_; }
    cl::Context& context() { return context_; }
    cl::CommandQueue& queue() { return queue_; }

    // The program whose main file is kernels/<mainFile>, built once per context. A build
    // failure throws DeviceError with the compiler's log.
    cl::Program& program(const std::string& mainFile);

    // The work-group size every kernel is launched with: a fixed size (measured on PoCL: 64,
    // 128 and 256 run alike, and each new size costs a compile), capped by the device.
    std::size_t workGroupSize() const;
    // For experiments and tests: launch with another size (results must not change).
    void setWorkGroupSize(std::size_t size);

private:
    DeviceDescription description_;
    cl::Context context_;
    cl::CommandQueue queue_;
    std::map<std::string, cl::Program> programs_;
    std::size_t workGroupSize_ = 0;
};

}  // namespace rad
