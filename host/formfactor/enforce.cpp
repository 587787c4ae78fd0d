#include "formfactor/enforce.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include "util/error.h"

namespace rad {
namespace {

using Triplet = std::tuple<std::uint32_t, std::uint32_t, double>;  // row, column, G

// G = A F, symmetrised: every stored (i, j) and its mirror get (G_ij + G_ji) / 2.
std::vector<std::vector<std::pair<std::uint32_t, double>>> symmetricG(const ViewFactorTable& t) {
    std::vector<Triplet> triplets;
    for (std::uint32_t i = 0; i < t.size(); ++i)
        for (const ViewFactorEntry& e : t.rows[i]) {
            const double g = t.areas[i] * e.factor / 2.0;
            triplets.emplace_back(i, e.to, g);
            triplets.emplace_back(e.to, i, g);
        }
    std::sort(triplets.begin(), triplets.end());
    std::vector<std::vector<std::pair<std::uint32_t, double>>> g(t.size());
    for (const auto& [i, j, value] : triplets) {
        if (!g[i].empty() && g[i].back().first == j) g[i].back().second += value;
        else g[i].emplace_back(j, value);
    }
    return g;
}

std::vector<std::vector<std::pair<std::uint32_t, double>>> plainG(const ViewFactorTable& t) {
    std::vector<std::vector<std::pair<std::uint32_t, double>>> g(t.size());
    for (std::uint32_t i = 0; i < t.size(); ++i)
        for (const ViewFactorEntry& e : t.rows[i]) g[i].emplace_back(e.to, t.areas[i] * e.factor);
    return g;
}

}  // namespace

Enforce parseEnforce(const std::string& name) {
    if (name == "none") return Enforce::None;
    if (name == "reciprocity") return Enforce::Reciprocity;
    if (name == "closure") return Enforce::Closure;
    if (name == "both") return Enforce::Both;
    throw InputError("--enforce " + name + ": use none, reciprocity, closure or both");
}

const char* enforceName(Enforce mode) {
    switch (mode) {
        case Enforce::None: return "none";
        case Enforce::Reciprocity: return "reciprocity";
        case Enforce::Closure: return "closure";
        case Enforce::Both: return "both";
    }
    return "none";
}

const char* enforceHelp() {
    return "correct the estimated view factors, changing them as little as possible: none; reciprocity (A_i F_ij = "
           "A_j F_ji); closure (each closed row scaled to sum 1; breaks reciprocity); both (reciprocal, and every "
           "closed row sums to 1). A row is closed when at most 0.1 % of its rays reached nothing; open rows (rays "
           "that leave to space, or stop on the black back of a single-sided face) are not scaled to sum 1: their "
           "share to space keeps its estimate, up to the noise reciprocity averages out. Default both: the factors then obey the laws exact ones obey, the "
           "net heats of a closed scene add up to zero, and the error is smaller (RMS error against the closed "
           "forms about 0.6 of the uncorrected on a closed cube, 0.7 to 0.8 on open pairs of squares); the largest "
           "change is reported";
}

EnforceSummary enforce(ViewFactorTable& table, Enforce mode, double closedBelow) {
    EnforceSummary summary;
    if (mode == Enforce::None) return summary;
    const std::size_t n = table.size();
    std::vector<char> closed(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
        closed[i] = table.missed[i] <= closedBelow && !table.rows[i].empty() && table.areas[i] > 0.0;
        summary.closedRows += closed[i];
    }
    auto g = mode == Enforce::Closure ? plainG(table) : symmetricG(table);
    std::vector<double> d(n, 1.0);
    if (mode == Enforce::Closure) {
        for (std::size_t i = 0; i < n; ++i) {
            if (!closed[i]) continue;
            double sum = 0.0;
            for (const auto& [j, v] : g[i]) sum += v;
            if (sum > 0.0) d[i] = table.areas[i] / sum;  // a row scale, not a symmetric one
        }
        for (std::size_t i = 0; i < n; ++i)
            for (auto& [j, v] : g[i]) v *= d[i];
    } else if (mode == Enforce::Both) {
        // Symmetric Sinkhorn-Knopp: d_i <- sqrt(d_i A_i / sum_j G_ij d_j) on closed rows.
        for (summary.iterations = 1; summary.iterations <= 100000; ++summary.iterations) {
            double worst = 0.0;
            for (std::size_t i = 0; i < n; ++i) {
                if (!closed[i]) continue;
                double sum = 0.0;
                for (const auto& [j, v] : g[i]) sum += v * d[j];
                if (!(sum > 0.0)) continue;
                worst = std::max(worst, std::fabs(d[i] * sum / table.areas[i] - 1.0));
                d[i] = std::sqrt(d[i] * table.areas[i] / sum);
            }
            if (worst < 1e-13) break;
        }
        for (std::size_t i = 0; i < n; ++i)
            for (auto& [j, v] : g[i]) v *= d[i] * d[j];
    }
    // Back to F = G / A, keeping the standard errors of entries that were there.
    for (std::size_t i = 0; i < n; ++i) {
        std::vector<ViewFactorEntry> row;
        const auto& old = table.rows[i];
        std::size_t k = 0;
        for (const auto& [j, v] : g[i]) {  // g's pattern holds every old entry (and mirrors)
            while (k < old.size() && old[k].to < j) ++k;
            const bool existed = k < old.size() && old[k].to == j;
            const double f = table.areas[i] > 0.0 ? v / table.areas[i] : 0.0;
            summary.largestChange = std::max(summary.largestChange, std::fabs(f - (existed ? old[k].factor : 0.0)));
            row.push_back({j, f, existed ? old[k].standardError : NAN});
        }
        table.rows[i] = std::move(row);
        if (closed[i] && mode != Enforce::Reciprocity) table.missed[i] = 0.0;
    }
    return summary;
}

}  // namespace rad
