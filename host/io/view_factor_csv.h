#pragma once
// View factors out, as CSV or Matrix Market.
//   CSV: header `from,to,F,stderr`, one row per ordered pair with F > 0, in row order; names
//        quoted (RFC 4180) when they hold commas, quotes or line breaks; stderr `nan` where the
//        estimator gives no statistical error (hemicube, gather).
//   Matrix Market: `coordinate real general`, 1-based indices, the row and column names in
//        comment lines, then one line per non-zero F.

#include <ostream>

#include "formfactor/view_factor_table.h"

namespace rad {

void writeViewFactorCsv(std::ostream& out, const ViewFactorTable& table);
void writeViewFactorMatrixMarket(std::ostream& out, const ViewFactorTable& table);

}  // namespace rad
