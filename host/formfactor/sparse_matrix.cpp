#include "formfactor/sparse_matrix.h"

#include <algorithm>

namespace rad {

float SparseMatrix::at(std::uint32_t row, std::uint32_t col) const {
    const auto first = column.begin() + static_cast<std::ptrdiff_t>(rowStart[row]);
    const auto last = column.begin() + static_cast<std::ptrdiff_t>(rowStart[row + 1]);
    const auto found = std::lower_bound(first, last, col);
    return found != last && *found == col ? value[static_cast<std::size_t>(found - column.begin())] : 0.0f;
}

}  // namespace rad
