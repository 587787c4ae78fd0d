#pragma once
// The one place the OpenCL C++ bindings are configured. The devices speak OpenCL C 1.2; Debian's
// opencl.hpp does not compile with a 3.0 target and a 1.2 minimum, so target 1.2.

#define CL_HPP_TARGET_OPENCL_VERSION 120
#define CL_HPP_MINIMUM_OPENCL_VERSION 120
#define CL_HPP_ENABLE_EXCEPTIONS
#include <CL/opencl.hpp>
