#pragma once
// Heat exchange out (radiosity exchange): per surface the net heats, and the exchange factors
// with the radiative conductors, as CSV or Matrix Market.
//   Net heats, CSV: `surface,area,emissivity,temperature,net_heat,net_flux,radiosity,irradiance,
//        net_heat_stderr,temperature_stderr,to_space,to_space_stderr`, one row per surface side
//        (`nan` error bars when a batch alone had no solution). to_space is the share of the
//        side's view that reaches no surface (1 - the row's sum of the uncorrected factors: space,
//        and the black backs of single-sided faces, which the net-radiation method counts as
//        environment too), its error bar the spread of the batches' shares over sqrt(batches).
//   Exchange, CSV: `from,to,exchange_factor,conductor`, one row per ordered pair with G > 0.
//   Exchange, Matrix Market: `coordinate real general`, 1-based, entry (i, j) the exchange
//        factor G_ij; comment lines give each surface's name, area and emissivity, from which
//        the conductor eps_i A_i G_ij follows.

#include <ostream>
#include <vector>

#include "formfactor/view_factor_table.h"
#include "thermal/radiative_exchange.h"

namespace rad {

void writeNetHeatCsv(std::ostream& out, const ExchangeEstimate& estimate);
void writeExchangeCsv(std::ostream& out, const ExchangeEstimate& estimate, const std::vector<std::vector<double>>& g);
void writeExchangeMatrixMarket(std::ostream& out, const ExchangeEstimate& estimate,
                               const std::vector<std::vector<double>>& g);

}  // namespace rad
