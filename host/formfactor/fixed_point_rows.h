#pragma once
// For estimators whose kernel writes each shooter's row whole (hemicube, gather): (patchCount
// + 1) 32-bit fixed-point values per shooter, in units of 2^-32, the last for what reached no
// patch. Runs such a kernel on a batch and turns its rows into sparse ones.

#include <cstdint>
#include <vector>

#include "cl/device_array.h"
#include "cl/kernel_pack.h"
#include "formfactor/estimator.h"

namespace rad {

// Runs such a kernel on a batch: its arguments `args` (the method's own set by the caller) get
// the shooter list, the shooter count, the patch count and the rows to write; `workItems` work
// items; returns the rows.
template <typename Args>
std::vector<rad_uint> runRowKernel(ComputeContext& compute, DeviceKernel<Args>& kernel, Args args,
                                   const std::vector<std::uint32_t>& shooters, std::uint32_t patches,
                                   std::size_t workItems) {
    const DeviceArray<rad_uint> list = DeviceArray<rad_uint>::upload(compute, shooters, "shooter list");
    const DeviceArray<rad_uint> rows = DeviceArray<rad_uint>::upload(
        compute, std::vector<rad_uint>(shooters.size() * (std::size_t{patches} + 1), 0), "form-factor rows",
        DeviceAccess::readWrite);
    args.shooters = list;
    args.shooterCount = static_cast<rad_uint>(shooters.size());
    args.patchCount = patches;
    args.rows = rows;
    kernel.launch(args, workItems);
    return rows.read();
}

// Sparse rows from the fixed-point values. With `renormalise` each row is divided by its sum
// (missed column included), which goes into weightSum; otherwise the values are form factors
// already and what they do not account for counts as missed.
FormFactorRows decodeFixedPointRows(const std::vector<rad_uint>& values, std::size_t rows, std::uint32_t patches,
                                    bool renormalise);

}  // namespace rad
