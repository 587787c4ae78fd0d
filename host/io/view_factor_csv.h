#pragma once
// View factors as CSV: header `from,to,F,stderr`, one row per ordered pair of surfaces with
// F > 0, in surface order. Names are quoted (RFC 4180) when they hold commas, quotes or
// line breaks.

#include <ostream>

#include "formfactor/surface_view_factors.h"

namespace rad {

void writeViewFactorCsv(std::ostream& out, const SurfaceViewFactors& factors);

}  // namespace rad
