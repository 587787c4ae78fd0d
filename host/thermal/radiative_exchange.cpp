#include "thermal/radiative_exchange.h"

#include <algorithm>
#include <cmath>

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
        batches.push_back(computeSurfaceViewFactors(scene, {perBatch, rad_hash2(options.seed, k)}));

    ExchangeEstimate e;
    e.raysPerSurface = perBatch * options.batches;
    e.table = surfaceTable(poolSurfaceViewFactors(batches));
    e.enforced = enforce(e.table, options.enforce);
    e.problem = problemOn(e.table, conditions, options.environmentTemperature);
    e.solution = solveNetRadiation(e.problem);

    const std::size_t n = e.table.size();
    std::vector<double> sum(n, 0.0), squares(n, 0.0);
    for (const SurfaceViewFactors& b : batches) {
        ViewFactorTable own = surfaceTable(b);
        enforce(own, options.enforce);
        const ExchangeSolution s = solveNetRadiation(problemOn(own, conditions, options.environmentTemperature));
        for (std::size_t i = 0; i < n; ++i) {
            sum[i] += s.netHeat[i];
            squares[i] += s.netHeat[i] * s.netHeat[i];
        }
    }
    const double k = static_cast<double>(options.batches);
    e.netHeatStandardError.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const double mean = sum[i] / k;
        e.netHeatStandardError[i] = std::sqrt(std::max(0.0, squares[i] / k - mean * mean) / (k - 1.0));
    }
    return e;
}

}  // namespace rad
