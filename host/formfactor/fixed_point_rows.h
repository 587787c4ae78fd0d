#pragma once
// For estimators whose kernel writes each shooter's row whole (hemicube, gather): (patchCount
// + 1) 32-bit fixed-point values per shooter, in units of 2^-32, the last for what reached no
// patch. Runs such a kernel on a batch and turns its rows into sparse ones.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "cl/compute_context.h"
#include "formfactor/estimator.h"

namespace rad {

// Uploads the shooter list, lets `bind` set the kernel's own arguments (after the scene's:
// the list, the shooter count, then what `bind` adds, the output last), launches `workItems`
// and reads the rows back. Device errors name `what`.
std::vector<cl_uint> runRowKernel(
    ComputeContext& compute, cl::Kernel& kernel, const std::vector<std::uint32_t>& shooters, std::uint32_t patches,
    std::size_t workItems, const std::function<void(cl::Kernel&, const cl::Buffer& list, const cl::Buffer& out)>& bind,
    const std::string& what);

// Sparse rows from the fixed-point values. With `renormalise` each row is divided by its sum
// (missed column included), which goes into weightSum; otherwise the values are form factors
// already and what they do not account for counts as missed.
FormFactorRows decodeFixedPointRows(const std::vector<cl_uint>& values, std::size_t rows, std::uint32_t patches,
                                    bool renormalise);

}  // namespace rad
