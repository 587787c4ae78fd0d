#pragma once
// Radiative exchange in a prepared scene: the surface view factors by ray shooting
// (formfactor/surface_view_factors.h), corrected (formfactor/enforce.h), then the
// net-radiation method (thermal/net_radiation.h), with standard errors from independent
// estimates.
//
// The rays per surface are split into `batches` independent estimates (their own seeds). The
// answer uses the factors of all rays together; each batch's factors are solved too, and the
// spread of the batch net heats divided by sqrt(batches) is the standard error of the answer
// (the factors' noise enters the net heats nearly linearly). It measures the estimator's
// actual variance, stratification included, where the binomial bound would overstate it.

#include <cstdint>
#include <string>
#include <vector>

#include "formfactor/enforce.h"
#include "formfactor/view_factor_table.h"
#include "parallel/process_group.h"
#include "prepared/prepared_scene.h"
#include "thermal/net_radiation.h"

namespace rad {

struct ExchangeOptions {
    std::uint64_t raysPerSurface = 1'000'000;  // over all batches
    std::uint32_t batches = 8;
    std::uint32_t seed = 1;
    Enforce enforce = kDefaultEnforce;
    double environmentTemperature = 0.0;  // K
    // The processes that divide each batch's surfaces (parallel/process_group.h); one when null.
    const ProcessGroup* group = nullptr;
};

struct ExchangeEstimate {
    ViewFactorTable table;    // the factors of all rays, corrected
    EnforceSummary enforced;  // what the correction changed
    ExchangeProblem problem;  // on `table`
    ExchangeSolution solution;
    std::vector<double> netHeatStandardError;      // W, per surface (0 where the flux is imposed)
    std::vector<double> temperatureStandardError;  // K, per surface (0 where the temperature is given)
    // NaN error bars when a batch alone has no solution (its noise drives an imposed-flux
    // surface below 0 K) though all the rays together have one.
    bool errorBars = true;
    // Per surface: the share of its rays that stopped on the black back of a single-sided face.
    // The net-radiation method counts them as leaving to the environment.
    std::vector<double> blackBackFraction;
    // Per surface: the share of its rays that reached no surface (left to space, or stopped on a
    // black back): 1 - the row's sum before the correction, of all rays together; and its
    // standard error, the spread of the batches' shares divided by sqrt(batches).
    std::vector<double> toSpace, toSpaceStandardError;
    std::uint64_t raysPerSurface = 0;  // cast in all (a multiple of the batches)
};

// `conditions`: one per surface side of the scene's mesh (Mesh::surfaces order).
ExchangeEstimate estimateExchange(const PreparedScene& scene, const std::vector<SurfaceCondition>& conditions,
                                  const ExchangeOptions& options);

// What an estimate should be read with: every surface that lost more than 0.1 % of its rays on
// the black back of a single-sided face, and error bars missing (NaN) with `batches` batches.
std::vector<std::string> exchangeWarnings(const ExchangeEstimate& estimate, std::uint32_t batches);

}  // namespace rad
