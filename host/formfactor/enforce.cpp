#include "formfactor/enforce.h"

#include <algorithm>
#include <cmath>
#include <tuple>

#include "util/error.h"

namespace rad {
namespace {

// One entry of G = A F as the correction works on it: its column, its value and the standard
// error of that value (NaN where the estimator gives none).
struct Cell {
    std::uint32_t column;
    double g;
    double error;
};
using CellRows = std::vector<std::vector<Cell>>;

double raysOf(const ViewFactorTable& t, std::size_t i) { return i < t.rays.size() ? t.rays[i] : 0.0; }

// The variance of row i's estimate of G_ij = A_i F_ij: A_i^2 F (1 - F) / rays_i, with F the
// combined value G / A_i rather than the row's own (an estimate of zero, from a row whose rays
// never found the other, is not thereby exact). NaN where the row has no statistical error.
double varianceOfRowEstimate(const ViewFactorTable& t, std::size_t i, double g) {
    const double rays = raysOf(t, i), area = t.areas[i];
    if (!(rays > 0.0) || !(area > 0.0)) return NAN;
    const double f = std::clamp(g / area, 0.0, 1.0);
    return area * area * f * (1.0 - f) / rays;
}

// G = A F made symmetric: each pair's two estimates, A_i F_ij from row i and A_j F_ji from row j,
// combined into the one of least variance. Row i's variance is about A_i G (1 - F_ij) / rays_i,
// so its weight is rays_i / (A_i (1 - F_ij)): the estimate from the denser rays counts more, and
// a row that sends nearly all its rays to the other is nearly exact. A small surface finds its share of a large one far
// more precisely than the large one's rays find the small one, and an equal-weight average
// would hand the small row half of the large row's noise, magnified by the ratio of the areas.
// Rows without ray counts (hemicube, gather) get equal weights: the nearest symmetric matrix in
// the Frobenius norm.
CellRows symmetricG(const ViewFactorTable& t) {
    struct Pair {
        std::uint32_t low, high;
        double fromLow, fromHigh;  // G as row `low` and row `high` estimated it
    };
    std::vector<Pair> pairs;
    for (std::uint32_t i = 0; i < t.size(); ++i)
        for (const ViewFactorEntry& e : t.rows[i]) {
            const double g = t.areas[i] * e.factor;
            const std::uint32_t low = std::min(i, e.to), high = std::max(i, e.to);
            pairs.push_back({low, high, i == low ? g : 0.0, i == high ? g : 0.0});
        }
    std::sort(pairs.begin(), pairs.end(),
              [](const Pair& a, const Pair& b) { return std::tie(a.low, a.high) < std::tie(b.low, b.high); });
    CellRows g(t.size());
    for (std::size_t k = 0; k < pairs.size();) {
        Pair p = pairs[k++];
        if (k < pairs.size() && pairs[k].low == p.low && pairs[k].high == p.high) {  // the mirror
            p.fromLow += pairs[k].fromLow;
            p.fromHigh += pairs[k].fromHigh;
            ++k;
        }
        if (p.low == p.high) {  // F_ii of a concave surface: its own and only estimate
            g[p.low].push_back({p.low, p.fromLow, std::sqrt(varianceOfRowEstimate(t, p.low, p.fromLow))});
            continue;
        }
        const double rl = raysOf(t, p.low), rh = raysOf(t, p.high);
        const bool weighted = rl > 0.0 && rh > 0.0 && t.areas[p.low] > 0.0 && t.areas[p.high] > 0.0;
        // Inverse variances, rays_i / (A_i (1 - F_ij)) up to a common factor, at the combined
        // value: start from 1 - F = 1, then a few fixed-point steps (each moves less). In logs,
        // scaled so the larger weight is 1: no overflow whatever the areas.
        double wl = 1.0, wh = 1.0;
        const auto combined = [&] { return (wl * p.fromLow + wh * p.fromHigh) / (wl + wh); };
        const auto weigh = [&](double lossLow, double lossHigh) {
            const double low = std::log(rl) - std::log(t.areas[p.low]) - std::log(lossLow);
            const double high = std::log(rh) - std::log(t.areas[p.high]) - std::log(lossHigh);
            const double top = std::max(low, high);
            wl = std::exp(low - top);
            wh = std::exp(high - top);
        };
        if (weighted) {
            weigh(1.0, 1.0);
            for (int step = 0; step < 4; ++step) {
                const double g = combined();
                weigh(std::max(1e-9, 1.0 - std::min(1.0, g / t.areas[p.low])),
                      std::max(1e-9, 1.0 - std::min(1.0, g / t.areas[p.high])));
            }
        }
        const double value = combined();
        double error = NAN;
        if (weighted)
            error = std::sqrt(wl * wl * varianceOfRowEstimate(t, p.low, value) +
                              wh * wh * varianceOfRowEstimate(t, p.high, value)) / (wl + wh);
        g[p.low].push_back({p.high, value, error});
        g[p.high].push_back({p.low, value, error});
    }
    for (auto& row : g)
        std::sort(row.begin(), row.end(), [](const Cell& a, const Cell& b) { return a.column < b.column; });
    return g;
}

CellRows plainG(const ViewFactorTable& t) {
    CellRows g(t.size());
    for (std::uint32_t i = 0; i < t.size(); ++i)
        for (const ViewFactorEntry& e : t.rows[i])
            g[i].push_back({e.to, t.areas[i] * e.factor, t.areas[i] * e.standardError});
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
           "share to space keeps its estimate, up to the noise reciprocity removes. Reciprocity combines the two rows' "
           "estimates of each pair, weighted by their binomial precision (the surface with the denser rays counts more). "
           "Default both: the factors then obey the laws exact ones obey, the "
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
            for (const Cell& c : g[i]) sum += c.g;
            if (sum > 0.0) d[i] = table.areas[i] / sum;  // a row scale, not a symmetric one
        }
        for (std::size_t i = 0; i < n; ++i)
            for (Cell& c : g[i]) {
                c.g *= d[i];
                c.error *= d[i];
            }
    } else if (mode == Enforce::Both) {
        // Symmetric Sinkhorn-Knopp: d_i <- sqrt(d_i A_i / sum_j G_ij d_j) on closed rows.
        for (summary.iterations = 1; summary.iterations <= 100000; ++summary.iterations) {
            double worst = 0.0;
            for (std::size_t i = 0; i < n; ++i) {
                if (!closed[i]) continue;
                double sum = 0.0;
                for (const Cell& c : g[i]) sum += c.g * d[c.column];
                if (!(sum > 0.0)) continue;
                worst = std::max(worst, std::fabs(d[i] * sum / table.areas[i] - 1.0));
                d[i] = std::sqrt(d[i] * table.areas[i] / sum);
            }
            if (worst < 1e-13) break;
        }
        // The scales' own noise is left out of the errors: they scale with the entries.
        for (std::size_t i = 0; i < n; ++i)
            for (Cell& c : g[i]) {
                c.g *= d[i] * d[c.column];
                c.error *= d[i] * d[c.column];
            }
    }
    // Back to F = G / A, with the standard errors of the corrected entries.
    for (std::size_t i = 0; i < n; ++i) {
        std::vector<ViewFactorEntry> row;
        const auto& old = table.rows[i];
        std::size_t k = 0;
        const double area = table.areas[i];
        for (const Cell& c : g[i]) {  // g's pattern holds every old entry (and mirrors)
            while (k < old.size() && old[k].to < c.column) ++k;
            const bool existed = k < old.size() && old[k].to == c.column;
            const double f = area > 0.0 ? c.g / area : 0.0;
            summary.largestChange = std::max(summary.largestChange, std::fabs(f - (existed ? old[k].factor : 0.0)));
            row.push_back({c.column, f, area > 0.0 ? c.error / area : NAN});
        }
        table.rows[i] = std::move(row);
        if (closed[i] && mode != Enforce::Reciprocity) table.missed[i] = 0.0;
    }
    return summary;
}

}  // namespace rad
