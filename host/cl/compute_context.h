#pragma once
// One OpenCL device with its context, an in-order queue and the programs built for it.

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "cl/device_list.h"
#include "cl/opencl.h"

namespace rad {

class ComputeContext;

// Device memory set aside for a group of buffers, given back when this is destroyed. Lets the
// program refuse, with the figures, a scene the device cannot hold before allocating anything.
class MemoryReservation {
public:
    MemoryReservation() = default;
    MemoryReservation(ComputeContext* owner, std::uint64_t bytes) : owner_(owner), bytes_(bytes) {}
    MemoryReservation(MemoryReservation&& other) noexcept { *this = std::move(other); }
    MemoryReservation& operator=(MemoryReservation&& other) noexcept;
    MemoryReservation(const MemoryReservation&) = delete;
    MemoryReservation& operator=(const MemoryReservation&) = delete;
    ~MemoryReservation();

private:
    ComputeContext* owner_ = nullptr;
    std::uint64_t bytes_ = 0;
};

class ComputeContext {
public:
    // Opens the device chooseDevice(selector) picks. With `profiling`, kernels launched through
    // launch() are timed on the device (kernelSeconds()).
    static std::shared_ptr<ComputeContext> open(const std::string& selector, bool profiling = false);

    explicit ComputeContext(DeviceDescription description, bool profiling = false);

    const DeviceDescription& description() const { return description_; }
    cl::Context& context() { return context_; }
    cl::CommandQueue& queue() { return queue_; }

    // The program whose main file is kernels/<mainFile>, built once per context. A build
    // failure throws DeviceError with the compiler's log.
    // `defines`: extra build options such as "-DRAD_ALPHA_MASKS"; each (file, defines) is built
    // once.
    cl::Program& program(const std::string& mainFile, const std::string& defines = "");

    // Builds OpenCL C source under `name` (for messages); the same options and errors.
    cl::Program build(const std::string& name, const std::string& source, const std::string& defines = "");

    // The work-group size every kernel is launched with: a fixed size (measured on PoCL: 64,
    // 128 and 256 run alike, and each new size costs a compile), capped by the device.
    std::size_t workGroupSize() const;
    // For experiments and tests: launch with another size (results must not change).
    void setWorkGroupSize(std::size_t size);

    // Sets aside `bytes` of device memory for `what`. Throws DeviceError with the figures
    // (needed, in use, the device's total) when the device cannot hold it, or when one of the
    // buffers (`largestBuffer`) exceeds the device's largest allocation.
    MemoryReservation reserve(std::uint64_t bytes, std::uint64_t largestBuffer, const std::string& what);
    std::uint64_t reservedBytes() const { return reserved_; }

    // Enqueues a 1-D kernel over `items` work items (rounded up to the work-group size).
    void launch(cl::Kernel& kernel, std::size_t items);

    // Waits for everything enqueued to finish.
    void finish();

    // Device seconds spent in each kernel (by name) launched since the last call; empty
    // without profiling. Waits for the queue to finish.
    std::map<std::string, double> takeKernelSeconds();

private:
    DeviceDescription description_;
    cl::Context context_;
    cl::CommandQueue queue_;
    std::map<std::string, cl::Program> programs_;
    std::size_t workGroupSize_ = 0;
    bool profiling_ = false;
    std::uint64_t reserved_ = 0;
    friend class MemoryReservation;
    std::vector<std::pair<std::string, cl::Event>> events_;
};

}  // namespace rad
