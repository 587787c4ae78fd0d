#include "formfactor/view_factor_table.h"

#include <algorithm>

namespace rad {
namespace {

double binomialError(double f, double rays) { return rays > 0 ? std::sqrt(std::max(0.0, f * (1.0 - f)) / rays) : NAN; }

}  // namespace

double ViewFactorTable::factor(std::size_t from, std::size_t to) const {
    for (const ViewFactorEntry& e : rows[from])
        if (e.to == to) return e.factor;
    return 0.0;
}

SpaceShares spaceShares(const ViewFactorTable& uncorrected) {
    SpaceShares out;
    for (std::size_t i = 0; i < uncorrected.size(); ++i) {
        out.share.push_back(std::max(0.0, uncorrected.missed[i]));
        out.standardError.push_back(i < uncorrected.missedError.size() ? uncorrected.missedError[i] : NAN);
    }
    return out;
}

ViewFactorTable surfaceTable(const SurfaceViewFactors& factors) {
    ViewFactorTable table;
    table.names = factors.names;
    table.areas = factors.areas;
    table.rows.resize(factors.size());
    for (std::size_t i = 0; i < factors.size(); ++i) {
        for (const auto& [to, hits] : factors.rows[i])
            table.rows[i].push_back({to, factors.factor(i, to), factors.standardError(i, to)});
        const double missed =
            static_cast<double>(factors.escaped[i] + factors.blackBack[i]) / static_cast<double>(factors.raysPerSurface);
        table.missed.push_back(missed);
        table.missedError.push_back(binomialError(missed, static_cast<double>(factors.raysPerSurface)));
        table.rays.push_back(static_cast<double>(factors.raysPerSurface));
    }
    return table;
}

ViewFactorTable surfaceTable(const Mesh& mesh, const PatchMatrix& matrix) {
    const std::uint32_t raysPerPatch = matrix.raysPerRow;
    const std::size_t surfaces = mesh.surfaces.size();
    ViewFactorTable table;
    table.rows.resize(surfaces);
    for (const MeshSurface& s : mesh.surfaces) {
        table.names.push_back(s.name);
        table.areas.push_back(s.area);
    }
    std::vector<double> sum(surfaces, 0.0), variance(surfaces, 0.0);
    for (std::size_t s = 0; s < surfaces; ++s) {
        const MeshSurface& surface = mesh.surfaces[s];
        double missed = 0.0, missedVariance = 0.0, squaredWeights = 0.0;
        for (std::uint32_t k = 0; k < surface.patchCount; ++k) {
            const std::uint32_t i = surface.firstPatch + k;
            const double weight = mesh.patches[i].area / surface.area;
            squaredWeights += weight * weight;
            // Per target surface: this patch's F to it, and (for rays) its binomial variance.
            std::vector<std::pair<std::uint32_t, double>> perTarget;
            for (std::uint64_t e = matrix.F.rowStart[i]; e < matrix.F.rowStart[i + 1]; ++e) {
                const std::uint32_t target = mesh.patches[matrix.F.column[e]].surface;
                if (perTarget.empty() || perTarget.back().first != target) perTarget.emplace_back(target, 0.0);
                perTarget.back().second += matrix.F.value[e];
            }
            std::sort(perTarget.begin(), perTarget.end());
            for (std::size_t a = 0; a < perTarget.size();) {  // merge runs of the same target
                std::size_t b = a;
                double f = 0.0;
                while (b < perTarget.size() && perTarget[b].first == perTarget[a].first) f += perTarget[b++].second;
                sum[perTarget[a].first] += weight * f;
                if (raysPerPatch > 0) variance[perTarget[a].first] += weight * weight * f * (1.0 - f) / raysPerPatch;
                a = b;
            }
            missed += weight * matrix.missed[i];
            const double m = matrix.missed[i];
            if (raysPerPatch > 0) missedVariance += weight * weight * std::max(0.0, m * (1.0 - m)) / raysPerPatch;
        }
        for (std::uint32_t t = 0; t < surfaces; ++t)
            if (sum[t] > 0.0) {
                table.rows[s].push_back({t, sum[t], raysPerPatch > 0 ? std::sqrt(variance[t]) : NAN});
                sum[t] = 0.0;
                variance[t] = 0.0;
            }
        table.missed.push_back(missed);
        table.missedError.push_back(raysPerPatch > 0 ? std::sqrt(missedVariance) : NAN);
        // The same rays per patch, patches weighted by area: n / sum(w^2) rays' worth.
        table.rays.push_back(raysPerPatch > 0 && squaredWeights > 0.0 ? raysPerPatch / squaredWeights : 0.0);
    }
    return table;
}

std::string patchName(const Mesh& mesh, std::size_t patch) {
    const MeshSurface& s = mesh.surfaces[mesh.patches[patch].surface];
    return s.name + "#" + std::to_string(patch - s.firstPatch);
}

ViewFactorTable patchTable(const Mesh& mesh, const PatchMatrix& matrix) {
    const std::uint32_t raysPerPatch = matrix.raysPerRow;
    ViewFactorTable table;
    const std::size_t patches = mesh.patches.size();
    table.rows.resize(patches);
    for (std::size_t i = 0; i < patches; ++i) {
        table.names.push_back(patchName(mesh, i));
        table.areas.push_back(mesh.patches[i].area);
        for (std::uint64_t e = matrix.F.rowStart[i]; e < matrix.F.rowStart[i + 1]; ++e) {
            const double f = matrix.F.value[e];
            table.rows[i].push_back({matrix.F.column[e], f, raysPerPatch > 0 ? binomialError(f, raysPerPatch) : NAN});
        }
        table.missed.push_back(matrix.missed[i]);
        table.missedError.push_back(raysPerPatch > 0 ? binomialError(matrix.missed[i], raysPerPatch) : NAN);
        table.rays.push_back(static_cast<double>(raysPerPatch));
    }
    return table;
}

}  // namespace rad
