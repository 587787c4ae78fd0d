#pragma once
// Every OpenCL failure becomes a DeviceError naming the call, the error and what we were doing.

#include <string>

#include "cl/opencl.h"
#include "util/error.h"

namespace rad {

class DeviceError : public RuntimeFailure {
public:
    using RuntimeFailure::RuntimeFailure;
};

// "CL_OUT_OF_RESOURCES" for -5, and so on; "unknown OpenCL error" for codes it does not know.
const char* clErrorName(cl_int code);

// Turns the bindings' cl::Error into a DeviceError: "<doing>: clBuildProgram failed with
// CL_BUILD_PROGRAM_FAILURE (-11)".
[[noreturn]] void throwDeviceError(const cl::Error& error, const std::string& doing);

}  // namespace rad
