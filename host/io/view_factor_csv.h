#pragma once
// View factors out, as CSV or Matrix Market.
//   CSV: header `from,to,F,stderr`, one row per ordered pair with F > 0, in row order; names
//        quoted (RFC 4180) when they hold commas, quotes or line breaks; stderr `nan` where the
//        estimator gives no statistical error (hemicube, gather).
//   Matrix Market: `coordinate real general`, 1-based indices, the row and column names in
//        comment lines, then one line per non-zero F.
//   To space (a file of its own, so the two above keep their form for the tools that read
//        them): header `from,area,to_space,stderr`, one row per row of the table, in its order
//        and with its names: the share of the row that left the scene (1 - the row's sum
//        before --enforce; rays stopped on the black back of a single-sided face count in it),
//        and its standard error (`nan` where the estimator gives none).

#include <ostream>

#include "formfactor/view_factor_table.h"

namespace rad {

void writeViewFactorCsv(std::ostream& out, const ViewFactorTable& table);
void writeViewFactorMatrixMarket(std::ostream& out, const ViewFactorTable& table);
void writeSpaceSharesCsv(std::ostream& out, const ViewFactorTable& table, const SpaceShares& space);

}  // namespace rad
