#include "cl/device_list.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>

#include "cl/error.h"
#include "util/error.h"

namespace rad {
namespace {

std::string trimmed(std::string s) {
    while (!s.empty() && (s.back() == '\0' || std::isspace(static_cast<unsigned char>(s.back())))) s.pop_back();
    return s;
}

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

std::string typeName(cl_device_type type) {
    if (type & CL_DEVICE_TYPE_GPU) return "gpu";
    if (type & CL_DEVICE_TYPE_CPU) return "cpu";
    if (type & CL_DEVICE_TYPE_ACCELERATOR) return "accelerator";
    return "other";
}

std::string summary(const std::vector<DeviceDescription>& devices) {
    std::string text;
    for (const auto& d : devices)
        text += (text.empty() ? "" : "; ") + std::to_string(d.index) + ": " + d.platform + " / " + d.name;
    return text;
}

}  // namespace

std::vector<DeviceDescription> listDevices() {
    std::vector<DeviceDescription> devices;
    std::vector<cl::Platform> platforms;
    try {
        cl::Platform::get(&platforms);
    } catch (const cl::Error&) {
        return devices;  // ocl-icd reports "no platform" as an error
    }
    for (const cl::Platform& platform : platforms) {
        std::vector<cl::Device> platformDevices;
        try {
            platform.getDevices(CL_DEVICE_TYPE_ALL, &platformDevices);
        } catch (const cl::Error&) {
            continue;  // a platform without devices
        }
        for (const cl::Device& device : platformDevices) {
            try {
                DeviceDescription d;
                d.index = devices.size();
                d.platform = trimmed(platform.getInfo<CL_PLATFORM_NAME>());
                d.vendor = trimmed(platform.getInfo<CL_PLATFORM_VENDOR>());
                d.name = trimmed(device.getInfo<CL_DEVICE_NAME>());
                d.type = typeName(device.getInfo<CL_DEVICE_TYPE>());
                d.version = trimmed(device.getInfo<CL_DEVICE_VERSION>());
                d.driver = trimmed(device.getInfo<CL_DRIVER_VERSION>());
                d.computeUnits = device.getInfo<CL_DEVICE_MAX_COMPUTE_UNITS>();
                d.globalMemory = device.getInfo<CL_DEVICE_GLOBAL_MEM_SIZE>();
                d.maxAllocation = device.getInfo<CL_DEVICE_MAX_MEM_ALLOC_SIZE>();
                d.maxWorkGroupSize = device.getInfo<CL_DEVICE_MAX_WORK_GROUP_SIZE>();
                d.correctlyRoundedDivideSqrt =
                    (device.getInfo<CL_DEVICE_SINGLE_FP_CONFIG>() & CL_FP_CORRECTLY_ROUNDED_DIVIDE_SQRT) != 0;
                d.device = device;
                devices.push_back(d);
            } catch (const cl::Error&) {
                continue;  // a device that cannot even describe itself is of no use
            }
        }
    }
    return devices;
}

DeviceDescription chooseDevice(const std::string& requested) {
    const char* fromEnvironment = std::getenv("RADIOSITY_DEVICE");
    const std::string selector = !requested.empty() ? requested : (fromEnvironment ? fromEnvironment : "");
    const std::vector<DeviceDescription> devices = listDevices();
    if (devices.empty())
        throw RuntimeFailure("no OpenCL device found: install an OpenCL driver (on Debian: apt install pocl-opencl-icd)");
    if (selector.empty()) return devices.front();
    if (std::all_of(selector.begin(), selector.end(), [](unsigned char c) { return std::isdigit(c); })) {
        const std::size_t index = selector.size() < 9 ? std::stoul(selector) : devices.size();
        if (index < devices.size()) return devices[index];
        throw InputError("device " + selector + ": there is no device with that index (" + summary(devices) + ")");
    }
    const std::string wanted = lower(selector);
    for (const auto& d : devices)
        if (wanted == d.type) return d;
    for (const auto& d : devices)
        if (lower(d.platform + " " + d.vendor + " " + d.name).find(wanted) != std::string::npos) return d;
    throw InputError("device '" + selector + "': no device matches (" + summary(devices) + ")");
}

}  // namespace rad
