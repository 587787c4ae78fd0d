#pragma once
// The OpenCL devices on this machine, across all platforms, and choosing one of them.

#include <cstdint>
#include <string>
#include <vector>

#include "cl/opencl.h"

namespace rad {

struct DeviceDescription {
    std::size_t index = 0;          // position in listDevices(), across platforms
    std::string platform;           // platform name, e.g. "Portable Computing Language"
    std::string vendor;             // platform vendor, e.g. "The pocl project"
    std::string name;               // device name
    std::string type;               // "cpu", "gpu", "accelerator" or "other"
    std::string version;            // CL_DEVICE_VERSION
    std::string driver;             // CL_DRIVER_VERSION
    unsigned computeUnits = 0;
    std::uint64_t globalMemory = 0; // bytes
    std::uint64_t maxAllocation = 0;
    std::size_t maxWorkGroupSize = 0;
    bool correctlyRoundedDivideSqrt = false;  // supports -cl-fp32-correctly-rounded-divide-sqrt
    cl::Device device;
};

// Every device of every platform; empty when no OpenCL platform is installed.
std::vector<DeviceDescription> listDevices();

// Picks a device by `selector` (or, when it is empty, by the environment variable
// RADIOSITY_DEVICE; with neither, the first device): an index from listDevices(); "cpu" or
// "gpu" for the first of that type; otherwise a case-insensitive part of the platform, vendor
// or device name ("pocl", "rusticl", "nvidia"). Throws InputError naming the choices when
// nothing matches, and RuntimeFailure when there is no device at all.
DeviceDescription chooseDevice(const std::string& selector);

}  // namespace rad
