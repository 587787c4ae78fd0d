#pragma once
// Kernels bound by name (kernels/packs.h says what a pack is). RAD_HOST_PACK(Struct, PACK) makes
// a struct with one field per entry of PACK, named as the kernel names its parameter: a
// DeviceView<type> for IN and OUT entries (so an array of another element type does not
// compile), a value of `type` for VALUE entries. DeviceKernel<Struct> binds such a struct in
// the pack's order and launches, turning OpenCL failures into DeviceErrors that name the kernel;
// a buffer left unset is refused by name before anything runs.

#include <cstddef>
#include <functional>
#include <string>
#include <utility>

#include <CL/cl_platform.h>
#include <glm/vec3.hpp>

#include "cl/compute_context.h"
#include "cl/device_array.h"
#include "cl/error.h"
#include "packs.h"
#include "util/error.h"

// The vector types packs name, as the host names them (the kernels' float4, uint4, ...).
using rad_float2 = cl_float2;
using rad_float4 = cl_float4;
using rad_uint2 = cl_uint2;
using rad_uint4 = cl_uint4;
using rad_ulong = cl_ulong;

namespace rad {

inline rad_float4 float4Of(const glm::vec3& v, float w = 0.0f) {
    return {{v.x, v.y, v.z, w}};
}

template <typename T>
void bindArgument(cl::Kernel& kernel, cl_uint index, const DeviceView<T>& view, const char* name) {
    if (view.buffer() == nullptr)
        throw RuntimeFailure(std::string("the argument '") + name + "' of the kernel " +
                             kernel.getInfo<CL_KERNEL_FUNCTION_NAME>() + " was not set");
    kernel.setArg(index, view.buffer);
}

template <typename T>
void bindArgument(cl::Kernel& kernel, cl_uint index, const DeviceArray<T>& array, const char* name) {
    bindArgument(kernel, index, array.view(), name);
}

template <typename T>
void bindArgument(cl::Kernel& kernel, cl_uint index, const T& value, const char*) {
    kernel.setArg(index, value);
}

#define RAD_HOST_FIELD_IN(type, name) ::rad::DeviceView<type> name;
#define RAD_HOST_FIELD_OUT(type, name) ::rad::DeviceView<type> name;
#define RAD_HOST_FIELD_VALUE(type, name) type name{};
#define RAD_HOST_FIELD(kind, type, name) RAD_HOST_FIELD_##kind(type, name)
#define RAD_HOST_BIND(kind, type, name) ::rad::bindArgument(kernel, index++, name, #name);
#define RAD_HOST_NAME(kind, type, name) #name,
#define RAD_HOST_COUNT(kind, type, name) +1

// struct Struct { fields of PACK; bind(kernel, first): sets them from argument `first` on and
// returns the index after them; kNames: the parameters' names in order, for the test that
// every kernel declares its parameters by its pack (tests/test_kernels.cpp) }.
#define RAD_HOST_PACK(Struct, PACK)                                                                   \
    struct Struct {                                                                                   \
        PACK(RAD_HOST_FIELD)                                                                          \
        cl_uint bind(cl::Kernel& kernel, cl_uint index) const {                                       \
            PACK(RAD_HOST_BIND)                                                                       \
            return index;                                                                             \
        }                                                                                             \
        static constexpr std::size_t kCount = 0 PACK(RAD_HOST_COUNT);                                 \
        static constexpr const char* kNames[kCount] = {PACK(RAD_HOST_NAME)};                          \
    };

// A kernel whose own parameters are the pack Args, after the parameters that `bindFirst` sets
// (a scene's buffers and the packs made with it: DeviceScene::kernel) and returns the count of.
// bindFirst runs again at every launch, so the kernel reads the buffers its maker holds then,
// not those of when it was made, and what it captures keeps its buffers alive.
template <typename Args>
class DeviceKernel {
public:
    using BindFirst = std::function<cl_uint(cl::Kernel&)>;

    DeviceKernel() = default;
    DeviceKernel(ComputeContext& compute, cl::Kernel kernel, BindFirst bindFirst = {})
        : compute_(&compute), kernel_(std::move(kernel)), bindFirst_(std::move(bindFirst)) {
        name_ = kernel_.getInfo<CL_KERNEL_FUNCTION_NAME>();
    }

    // Runs it over `items` work items (rounded up to the work-group size).
    void launch(const Args& args, std::size_t items) {
        try {
            args.bind(kernel_, bindFirst_ ? bindFirst_(kernel_) : 0);
            compute_->launch(kernel_, items);
        } catch (const cl::Error& e) {
            throwDeviceError(e, "running the kernel " + name_);
        }
    }

    // Runs it over `groups` work groups of the context's size (kernels that take work in groups).
    void launchGroups(const Args& args, std::size_t groups) { launch(args, groups * compute_->workGroupSize()); }

    const std::string& name() const { return name_; }

private:
    ComputeContext* compute_ = nullptr;
    cl::Kernel kernel_;
    BindFirst bindFirst_;
    std::string name_;
};

// The kernel `name` of the program kernels/<file> with Args as its whole parameter list (kernels
// that read no scene; DeviceScene::kernel makes those that do).
template <typename Args>
DeviceKernel<Args> makeKernel(ComputeContext& compute, const std::string& file, const char* name) {
    try {
        return DeviceKernel<Args>(compute, cl::Kernel(compute.program(file), name));
    } catch (const cl::Error& e) {
        throwDeviceError(e, std::string("creating the kernel ") + name);
    }
}

}  // namespace rad
