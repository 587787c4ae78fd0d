#pragma once
// A sparse matrix in compressed rows (CSR): what form-factor matrices are stored as, since a
// patch sees only part of the scene.

#include <cstdint>
#include <vector>

namespace rad {

struct SparseMatrix {
    std::uint32_t columns = 0;
    std::vector<std::uint64_t> rowStart{0};  // rows + 1 entries; row i is [rowStart[i], rowStart[i + 1])
    std::vector<std::uint32_t> column;
    std::vector<float> value;

    std::uint32_t rows() const { return static_cast<std::uint32_t>(rowStart.size() - 1); }
    std::uint64_t nonZeros() const { return value.size(); }
    std::uint64_t bytes() const {
        return rowStart.size() * sizeof(std::uint64_t) + column.size() * sizeof(std::uint32_t) + value.size() * sizeof(float);
    }
    void appendRow(const std::vector<std::pair<std::uint32_t, float>>& entries) {
        for (const auto& [c, v] : entries) {
            column.push_back(c);
            value.push_back(v);
        }
        rowStart.push_back(value.size());
    }
    double rowSum(std::uint32_t row) const {
        double sum = 0.0;
        for (std::uint64_t k = rowStart[row]; k < rowStart[row + 1]; ++k) sum += value[k];
        return sum;
    }
    float at(std::uint32_t row, std::uint32_t col) const;  // 0 where nothing is stored
};

}  // namespace rad
