#pragma once
// Typed device buffers: uploads, allocations, reads and writes that size themselves from their
// element type. Uploads and allocations turn OpenCL failures into a DeviceError naming the
// buffer; reads and writes are queued commands, whose failures (cl::Error) the operation that
// queued them turns into a DeviceError naming itself. The one place host code creates buffers
// from data, so nothing else repeats the flags, the casts or the rule that an OpenCL buffer
// cannot be empty.

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "cl/compute_context.h"
#include "cl/error.h"
#include "util/format.h"

namespace rad {

// Bytes a buffer of `count` T takes: at least one T, since OpenCL buffers cannot be empty.
template <typename T>
std::uint64_t bufferBytes(std::size_t count) {
    return std::max<std::uint64_t>(1, count) * sizeof(T);
}

// A buffer holding a copy of `data` (one zeroed T when data is empty).
template <typename T>
cl::Buffer uploadBuffer(ComputeContext& compute, const std::vector<T>& data, const std::string& what,
                        cl_mem_flags access = CL_MEM_READ_ONLY) {
    static const T empty{};
    const void* source = data.empty() ? static_cast<const void*>(&empty) : static_cast<const void*>(data.data());
    try {
        return cl::Buffer(compute.context(), access | CL_MEM_COPY_HOST_PTR, bufferBytes<T>(data.size()),
                          const_cast<void*>(source));
    } catch (const cl::Error& e) {
        throwDeviceError(e, "uploading the " + what + " (" + byteSize(bufferBytes<T>(data.size())) + ")");
    }
}

// An uninitialised buffer of `count` T.
template <typename T>
cl::Buffer allocateBuffer(ComputeContext& compute, std::size_t count, const std::string& what,
                          cl_mem_flags access = CL_MEM_READ_WRITE) {
    try {
        return cl::Buffer(compute.context(), access, bufferBytes<T>(count));
    } catch (const cl::Error& e) {
        throwDeviceError(e, "allocating the " + what + " (" + byteSize(bufferBytes<T>(count)) + ")");
    }
}

// The first `count` T of `buffer`, waiting for the queue to reach the read.
template <typename T>
std::vector<T> readBuffer(ComputeContext& compute, const cl::Buffer& buffer, std::size_t count) {
    std::vector<T> out(count);
    if (count > 0) compute.queue().enqueueReadBuffer(buffer, CL_TRUE, 0, count * sizeof(T), out.data());
    return out;
}

// Enqueues a read of into.size() T and returns: `into` must stay alive, untouched, until the
// queue has finished (a later blocking read does that).
template <typename T>
void enqueueRead(ComputeContext& compute, const cl::Buffer& buffer, std::vector<T>& into) {
    if (!into.empty()) compute.queue().enqueueReadBuffer(buffer, CL_FALSE, 0, into.size() * sizeof(T), into.data());
}

// Enqueues a write of `data` and returns: `data` must stay alive, unchanged, until the queue has
// finished.
template <typename T>
void enqueueWrite(ComputeContext& compute, cl::Buffer& buffer, const std::vector<T>& data) {
    if (!data.empty()) compute.queue().enqueueWriteBuffer(buffer, CL_FALSE, 0, data.size() * sizeof(T), data.data());
}

inline cl_float4 float4Of(const glm::vec3& v, float w = 0.0f) {
    return {{v.x, v.y, v.z, w}};
}

// Sets a kernel's arguments from index `first` on, in order. Scalars must have the kernel's
// types (cl_uint, float, ...): cast at the call, as the kernel's signature reads.
template <typename... Args>
void setKernelArgs(cl::Kernel& kernel, cl_uint first, const Args&... args) {
    (kernel.setArg(first++, args), ...);
}

}  // namespace rad
