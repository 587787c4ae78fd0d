#include <cstdio>

#include "app/commands.h"
#include "cl/device_list.h"
#include "util/error.h"

namespace rad {

void runDevices() {
    const auto devices = listDevices();
    if (devices.empty())
        throw RuntimeFailure("no OpenCL device found: install an OpenCL driver (on Debian: apt install pocl-opencl-icd)");
    for (const DeviceDescription& d : devices) {
        std::printf("%zu: %s / %s (%s, %u compute units, %llu MiB, %s, driver %s)\n", d.index, d.platform.c_str(),
                    d.name.c_str(), d.type.c_str(), d.computeUnits,
                    static_cast<unsigned long long>(d.globalMemory >> 20), d.version.c_str(), d.driver.c_str());
    }
}

}  // namespace rad
