#pragma once
// Typed arrays on the device: the one way host code gets device memory. An array sets its bytes
// aside on the device when it is made (ComputeContext::reserve, which refuses with the figures
// what the device cannot hold) and gives them back when it is destroyed; every OpenCL failure
// becomes a DeviceError naming the array. Kernels take arrays through their argument packs
// (cl/kernel_pack.h), which check the element type against the kernel's declaration.

#include <algorithm>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "cl/compute_context.h"
#include "cl/error.h"
#include "util/format.h"

namespace rad {

// How kernels use an array; it decides the OpenCL memory flags.
enum class DeviceAccess { read, write, readWrite };

// A device buffer of T and its element count, as a kernel argument sees it.
template <typename T>
struct DeviceView {
    cl::Buffer buffer;
    std::size_t count = 0;
};

template <typename T>
class DeviceArray {
public:
    DeviceArray() = default;
    DeviceArray(DeviceArray&&) noexcept = default;
    DeviceArray& operator=(DeviceArray&&) noexcept = default;

    // A copy of `data` (one zeroed T when `data` is empty: OpenCL buffers cannot be empty, and a
    // kernel may read the placeholder).
    static DeviceArray upload(ComputeContext& compute, const std::vector<T>& data, const std::string& what,
                              DeviceAccess access = DeviceAccess::read) {
        static const T empty{};
        DeviceArray array(compute, data.size(), what);
        const void* source = data.empty() ? static_cast<const void*>(&empty) : static_cast<const void*>(data.data());
        try {
            array.buffer_ = cl::Buffer(compute.context(), flags(access) | CL_MEM_COPY_HOST_PTR, array.bytes(),
                                       const_cast<void*>(source));
        } catch (const cl::Error& e) {
            throwDeviceError(e, "uploading the " + what + " (" + byteSize(array.bytes()) + ")");
        }
        return array;
    }

    // `count` T, uninitialised.
    static DeviceArray allocate(ComputeContext& compute, std::size_t count, const std::string& what,
                                DeviceAccess access = DeviceAccess::readWrite) {
        DeviceArray array(compute, count, what);
        try {
            array.buffer_ = cl::Buffer(compute.context(), flags(access), array.bytes());
        } catch (const cl::Error& e) {
            throwDeviceError(e, "allocating the " + what + " (" + byteSize(array.bytes()) + ")");
        }
        return array;
    }

    std::size_t size() const { return count_; }
    std::uint64_t bytes() const { return std::max<std::uint64_t>(1, count_) * sizeof(T); }
    const std::string& what() const { return what_; }
    DeviceView<T> view() const { return {buffer_, count_}; }
    operator DeviceView<T>() const { return view(); }  // NOLINT: an array binds where its view does

    // The first `count` T (all of them by default), waiting for the queue to reach the read.
    std::vector<T> read(std::size_t count) const {
        std::vector<T> out(count);
        if (count > 0) {
            try {
                compute_->queue().enqueueReadBuffer(buffer_, CL_TRUE, 0, count * sizeof(T), out.data());
            } catch (const cl::Error& e) {
                throwDeviceError(e, "reading the " + what_);
            }
        }
        return out;
    }
    std::vector<T> read() const { return read(count_); }

    // Enqueues a read of into.size() T and returns: `into` must stay alive, untouched, until the
    // queue has finished (a later blocking read, or ComputeContext::finish, does that).
    void enqueueRead(std::vector<T>& into) const {
        if (into.empty()) return;
        try {
            compute_->queue().enqueueReadBuffer(buffer_, CL_FALSE, 0, into.size() * sizeof(T), into.data());
        } catch (const cl::Error& e) {
            throwDeviceError(e, "reading the " + what_);
        }
    }

    // Enqueues a write of `data` from the first T on and returns: `data` must stay alive,
    // unchanged, until the queue has finished.
    void enqueueWrite(const std::vector<T>& data) {
        if (data.empty()) return;
        try {
            compute_->queue().enqueueWriteBuffer(buffer_, CL_FALSE, 0, data.size() * sizeof(T), data.data());
        } catch (const cl::Error& e) {
            throwDeviceError(e, "writing the " + what_);
        }
    }

    // Enqueues setting every element to `value`.
    void fill(const T& value) {
        try {
            compute_->queue().enqueueFillBuffer(buffer_, value, 0, bytes());
        } catch (const cl::Error& e) {
            throwDeviceError(e, "clearing the " + what_);
        }
    }

private:
    DeviceArray(ComputeContext& compute, std::size_t count, const std::string& what)
        : compute_(&compute), count_(count), what_(what) {
        reservation_ = compute.reserve(bytes(), bytes(), "the " + what);
    }

    static cl_mem_flags flags(DeviceAccess access) {
        switch (access) {
            case DeviceAccess::read: return CL_MEM_READ_ONLY;
            case DeviceAccess::write: return CL_MEM_WRITE_ONLY;
            case DeviceAccess::readWrite: return CL_MEM_READ_WRITE;
        }
        return CL_MEM_READ_WRITE;
    }

    ComputeContext* compute_ = nullptr;
    cl::Buffer buffer_;
    std::size_t count_ = 0;
    std::string what_;
    MemoryReservation reservation_;
};

}  // namespace rad
