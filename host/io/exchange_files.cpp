#include "io/exchange_files.h"

#include <string>

#include "io/csv_text.h"

namespace rad {
void writeNetHeatCsv(std::ostream& out, const ExchangeEstimate& e) {
    out << "surface,area,emissivity,temperature,net_heat,net_flux,radiosity,irradiance,net_heat_stderr,"
           "temperature_stderr,to_space,to_space_stderr\n";
    const ExchangeSolution& s = e.solution;
    for (std::size_t i = 0; i < e.table.size(); ++i)
        out << csvField(e.table.names[i]) << ',' << csvNumber(e.table.areas[i], 9) << ','
            << csvNumber(e.problem.conditions[i].emissivity, 9) << ',' << csvNumber(s.temperature[i], 9) << ','
            << csvNumber(s.netHeat[i], 9) << ',' << csvNumber(s.netFlux[i], 9) << ',' << csvNumber(s.radiosity[i], 9)
            << ',' << csvNumber(s.irradiance[i], 9) << ',' << csvNumber(e.netHeatStandardError[i], 3) << ','
            << csvNumber(e.temperatureStandardError[i], 3) << ',' << csvNumber(e.toSpace[i], 9) << ','
            << csvNumber(e.toSpaceStandardError[i], 3) << '\n';
}

void writeExchangeCsv(std::ostream& out, const ExchangeEstimate& e, const std::vector<std::vector<double>>& g) {
    out << "from,to,exchange_factor,conductor\n";
    for (std::size_t i = 0; i < g.size(); ++i)
        for (std::size_t j = 0; j < g.size(); ++j)
            if (g[i][j] > 0.0)
                out << csvField(e.table.names[i]) << ',' << csvField(e.table.names[j]) << ',' << csvNumber(g[i][j], 9)
                    << ',' << csvNumber(e.problem.conditions[i].emissivity * e.table.areas[i] * g[i][j], 9) << '\n';
}

void writeExchangeMatrixMarket(std::ostream& out, const ExchangeEstimate& e,
                               const std::vector<std::vector<double>>& g) {
    std::size_t nonZeros = 0;
    for (const auto& row : g)
        for (double v : row) nonZeros += v > 0.0;
    out << "%%MatrixMarket matrix coordinate real general\n";
    out << "% radiosity exchange factors: entry (i, j) is G_ij, the fraction of the power i emits that j absorbs;"
           " the radiative conductor is emissivity_i area_i G_ij (m^2)\n";
    for (std::size_t i = 0; i < g.size(); ++i)
        out << "% " << i + 1 << " " << oneLine(e.table.names[i]) << " area " << csvNumber(e.table.areas[i], 9)
            << " emissivity " << csvNumber(e.problem.conditions[i].emissivity, 9) << '\n';
    out << g.size() << ' ' << g.size() << ' ' << nonZeros << '\n';
    for (std::size_t i = 0; i < g.size(); ++i)
        for (std::size_t j = 0; j < g.size(); ++j)
            if (g[i][j] > 0.0) out << i + 1 << ' ' << j + 1 << ' ' << csvNumber(g[i][j], 9) << '\n';
}

}  // namespace rad
