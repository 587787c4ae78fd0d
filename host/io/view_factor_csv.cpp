#include "io/view_factor_csv.h"

#include <string>

#include "io/csv_text.h"

namespace rad {
void writeViewFactorCsv(std::ostream& out, const ViewFactorTable& table) {
    out << "from,to,F,stderr\n";
    for (std::size_t i = 0; i < table.size(); ++i)
        for (const ViewFactorEntry& e : table.rows[i]) {
            if (!(e.factor > 0.0)) continue;
            out << csvField(table.names[i]) << ',' << csvField(table.names[e.to]) << ',' << csvNumber(e.factor, 9) << ','
                << csvNumber(e.standardError, 3) << '\n';
        }
}

void writeViewFactorMatrixMarket(std::ostream& out, const ViewFactorTable& table) {
    std::size_t nonZeros = 0;
    for (const auto& row : table.rows)
        for (const ViewFactorEntry& e : row) nonZeros += e.factor > 0.0;
    out << "%%MatrixMarket matrix coordinate real general\n";
    out << "% radiosity view factors: entry (i, j) is F_ij, the fraction of the power leaving i that reaches j\n";
    for (std::size_t i = 0; i < table.size(); ++i)
        out << "% " << i + 1 << " " << oneLine(table.names[i]) << " area " << csvNumber(table.areas[i], 9) << '\n';
    out << table.size() << ' ' << table.size() << ' ' << nonZeros << '\n';
    for (std::size_t i = 0; i < table.size(); ++i)
        for (const ViewFactorEntry& e : table.rows[i])
            if (e.factor > 0.0) out << i + 1 << ' ' << e.to + 1 << ' ' << csvNumber(e.factor, 9) << '\n';
}

void writeSpaceSharesCsv(std::ostream& out, const ViewFactorTable& table, const SpaceShares& space) {
    out << "from,area,to_space,stderr\n";
    for (std::size_t i = 0; i < table.size(); ++i)
        out << csvField(table.names[i]) << ',' << csvNumber(table.areas[i], 9) << ',' << csvNumber(space.share[i], 9)
            << ',' << csvNumber(space.standardError[i], 3) << '\n';
}

}  // namespace rad
