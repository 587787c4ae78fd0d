#include "formfactor/fixed_point_rows.h"

#include <algorithm>
#include <numeric>

#include "cl/buffers.h"
#include "cl/error.h"

namespace rad {
namespace {

constexpr double kUnit = 4294967296.0;  // kernels write F in units of 2^-32

}  // namespace

std::vector<cl_uint> runRowKernel(
    ComputeContext& compute, cl::Kernel& kernel, const std::vector<std::uint32_t>& shooters, std::uint32_t patches,
    std::size_t workItems, const std::function<void(cl::Kernel&, const cl::Buffer& list, const cl::Buffer& out)>& bind,
    const std::string& what) {
    const std::size_t count = shooters.size() * (std::size_t{patches} + 1);
    try {
        const cl::Buffer list = uploadBuffer(compute, shooters, "shooter list");
        const cl::Buffer out =
            uploadBuffer(compute, std::vector<cl_uint>(count, 0), "form-factor rows", CL_MEM_READ_WRITE);
        bind(kernel, list, out);
        compute.launch(kernel, workItems);
        return readBuffer<cl_uint>(compute, out, count);
    } catch (const cl::Error& e) {
        throwDeviceError(e, "computing " + what + " form factors");
    }
}

FormFactorRows decodeFixedPointRows(const std::vector<cl_uint>& values, std::size_t rows, std::uint32_t patches,
                                    bool renormalise) {
    FormFactorRows batch;
    for (std::size_t r = 0; r < rows; ++r) {
        const cl_uint* row = values.data() + r * (std::size_t{patches} + 1);
        double total = renormalise ? std::accumulate(row, row + patches + 1, 0.0) : kUnit;
        if (!(total > 0.0)) total = kUnit;
        FormFactorRow entries;
        double sum = 0.0;
        for (std::uint32_t j = 0; j < patches; ++j)
            if (row[j] != 0) {
                entries.emplace_back(j, static_cast<float>(row[j] / total));
                sum += row[j] / total;
            }
        batch.rows.push_back(std::move(entries));
        batch.missed.push_back(renormalise ? static_cast<float>(row[patches] / total)
                                           : static_cast<float>(std::max(0.0, 1.0 - sum)));
        if (renormalise) batch.weightSum += total / kUnit;
    }
    return batch;
}

}  // namespace rad
