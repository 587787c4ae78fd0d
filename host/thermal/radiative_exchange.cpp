#include "thermal/radiative_exchange.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "formfactor/surface_view_factors.h"
#include "shared_math.h"
#include "util/error.h"

namespace rad {
namespace {

// The problem on a table of factors, dense.
ExchangeProblem problemOn(const ViewFactorTable& table, const std::vector<SurfaceCondition>& conditions,
                          double environmentTemperature) {
    ExchangeProblem p;
    p.area = table.areas;
    p.conditions = conditions;
    p.environmentTemperature = environmentTemperature;
    p.factor.assign(table.size(), std::vector<double>(table.size(), 0.0));
    for (std::size_t i = 0; i < table.size(); ++i)
        for (const ViewFactorEntry& e : table.rows[i]) p.factor[i][e.to] = e.factor;
    return p;
}

}  // namespace

ExchangeEstimate estimateExchange(const PreparedScene& scene, const std::vector<SurfaceCondition>& conditions,
                                  const ExchangeOptions& options) {
    if (options.batches < 2) throw InputError("the error bars need at least 2 batches");
    if (options.raysPerSurface < options.batches)
        throw InputError(std::to_string(options.raysPerSurface) + " rays per surface cannot be split into " +
                         std::to_string(options.batches) + " batches");
    if (conditions.size() != scene.mesh().surfaces.size())
        throw InputError("the thermal properties cover " + std::to_string(conditions.size()) + " surfaces of " +
                         std::to_string(scene.mesh().surfaces.size()));
    const std::uint64_t perBatch = options.raysPerSurface / options.batches;
    std::vector<SurfaceViewFactors> batches;
    for (std::uint32_t k = 0; k < options.batches; ++k)
        batches.push_back(computeSurfaceViewFactors(scene, ViewFactorOptions{perBatch, rad_hash2(options.seed, k)},
                                                    options.group ? *options.group : oneProcess()));

    ExchangeEstimate e;
    e.raysPerSurface = perBatch * options.batches;
    const SurfaceViewFactors all = poolSurfaceViewFactors(batches);
    e.table = surfaceTable(all);
    e.toSpace = spaceShares(e.table).share;  // before the correction closes rows
    e.enforced = enforce(e.table, options.enforce);
    e.problem = problemOn(e.table, conditions, options.environmentTemperature);
    e.solution = solveNetRadiation(e.problem);
    const std::size_t n = e.table.size();
    for (std::size_t i = 0; i < n; ++i)
        e.blackBackFraction.push_back(static_cast<double>(all.blackBack[i]) / static_cast<double>(all.raysPerSurface));

    // Each batch alone, then the spread of its answers about their mean (two passes).
    std::vector<std::vector<double>> heat, temperature, space;
    for (const SurfaceViewFactors& b : batches) {
        ViewFactorTable own = surfaceTable(b);
        space.push_back(spaceShares(own).share);  // needs no solution: every batch has it
        enforce(own, options.enforce);
        try {
            const ExchangeSolution s = solveNetRadiation(problemOn(own, conditions, options.environmentTemperature));
            heat.push_back(s.netHeat);
            temperature.push_back(s.temperature);
        } catch (const InputError&) {
            e.errorBars = false;
            break;
        }
    }
    const auto standardErrors = [&](const std::vector<std::vector<double>>& values) {
        std::vector<double> out(n, std::numeric_limits<double>::quiet_NaN());
        if (values.size() < 2) return out;
        const double k = static_cast<double>(values.size());
        for (std::size_t i = 0; i < n; ++i) {
            double mean = 0.0, squares = 0.0;
            for (const auto& v : values) mean += v[i] / k;
            for (const auto& v : values) squares += (v[i] - mean) * (v[i] - mean);
            out[i] = std::sqrt(squares / (k - 1.0) / k);
        }
        return out;
    };
    if (!e.errorBars) {
        heat.clear();
        temperature.clear();
    }
    e.netHeatStandardError = standardErrors(heat);
    e.temperatureStandardError = standardErrors(temperature);
    for (std::size_t k = space.size(); k < batches.size(); ++k)
        space.push_back(spaceShares(surfaceTable(batches[k])).share);
    e.toSpaceStandardError = standardErrors(space);
    return e;
}

std::vector<std::string> exchangeWarnings(const ExchangeEstimate& estimate, std::uint32_t batches) {
    std::vector<std::string> warnings = blackBackWarnings(
        estimate.table.names, estimate.blackBackFraction,
        "exchange counts them as leaving to the environment, so no heat is exchanged with those backs");
    char text[200];
    if (!estimate.errorBars) {
        std::snprintf(text, sizeof text,
                      "a batch of %llu rays alone has no solution with temperatures >= 0 K, so no error bars (nan); "
                      "give more --rays or fewer --batches",
                      static_cast<unsigned long long>(estimate.raysPerSurface / batches));
        warnings.push_back(text);
    }
    return warnings;
}

}  // namespace rad
