#include "formfactor/fixed_point_rows.h"

#include <algorithm>
#include <numeric>


namespace rad {
namespace {

constexpr double kUnit = 4294967296.0;  // kernels write F in units of 2^-32

}  // namespace

FormFactorRows decodeFixedPointRows(const std::vector<rad_uint>& values, std::size_t rows, std::uint32_t patches,
                                    bool renormalise) {
    FormFactorRows batch;
    for (std::size_t r = 0; r < rows; ++r) {
        const rad_uint* row = values.data() + r * (std::size_t{patches} + 1);
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
