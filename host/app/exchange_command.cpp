// radiosity exchange: radiative heat exchange between grey, diffuse surfaces at given
// temperatures or imposed fluxes, on the surface view factors that `viewfactors` computes,
// with error bars from independent estimates of those factors (thermal/radiative_exchange.h).

#include <cmath>
#include <cstdio>
#include <iostream>

#include <CLI/CLI.hpp>

#include "app/commands.h"
#include "app/console.h"
#include "formfactor/enforce.h"
#include "formfactor/sampling_checks.h"
#include "formfactor/view_factor_table.h"
#include "io/atomic_file.h"
#include "io/exchange_files.h"
#include "io/vtu_file.h"
#include "prepared/prepared_scene.h"
#include "scene/scene_files.h"
#include "thermal/radiative_exchange.h"
#include "thermal/thermal_properties.h"
#include "util/error.h"
#include "util/stopwatch.h"

namespace rad {
namespace {}  // namespace

CLI::App* addExchangeCommand(CLI::App& app, ExchangeArgs& args) {
    CLI::App* cmd = app.add_subcommand(
        "exchange", "Radiative heat exchange between grey, diffuse surfaces (net-radiation method), as CSV.");
    DeclaredOptions options(cmd);
    addSceneInputOptions(options, args.input);
    options.bind(OptionSpec::text("--properties",
                                  "CSV with the header surface,emissivity,temperature (K) or "
                                  "surface,emissivity,heat_flux (W/m^2 imposed), one row per surface side as "
                                  "viewfactors names them")
                     .mandatory(),
                 args.properties);
    options.bind(OptionSpec::positive("--default-emissivity",
                                      "emissivity of the surfaces the properties do not list (with "
                                      "--default-temperature)"),
                 args.defaultEmissivity);
    options.bind(OptionSpec::fraction("--default-temperature",
                                      "temperature (K) of the surfaces the properties do not list (with "
                                      "--default-emissivity)",
                                      -1.0, 0.0, 1e9),
                 args.defaultTemperature);
    options.bind(OptionSpec::fraction("--environment-temperature",
                                      "temperature (K) of the black environment that receives what leaves an open "
                                      "scene",
                                      0.0, 0.0, 1e9),
                 args.environmentTemperature);
    options.bind(OptionSpec::count("--rays", "rays cast from each surface in all, over all batches", 1'000'000, 1,
                                   4294967295.0),
                 args.rays);
    options.bind(OptionSpec::count("--batches",
                                   "independent estimates the rays are split into; their spread gives the standard "
                                   "errors",
                                   8, 2, 1000),
                 args.batches);
    options.bind(OptionSpec::choice("--enforce", enforceHelp(), enforceName(kDefaultEnforce),
                                    {"none", "reciprocity", "closure", "both"}),
                 args.enforce);
    options.bind(OptionSpec::text("--output", "write the CSV to this file instead of standard output"), args.output);
    options.bind(OptionSpec::text("--exchange",
                                  "also write the exchange (Gebhart) factors and radiative conductors eps_i A_i G_ij "
                                  "here"),
                 args.exchange);
    options.bind(OptionSpec::choice("--exchange-format",
                                    "csv (from,to,exchange_factor,conductor) or mtx (Matrix Market of the exchange "
                                    "factors, with each surface's area and emissivity in comments)",
                                    "csv", {"csv", "mtx"}),
                 args.exchangeFormat);
    options.bind(OptionSpec::text("--vtu",
                                  "also write the results on the geometry to this VTK file for ParaView (.vtu, one "
                                  "triangle per patch with its surface's net flux W/m^2, its part of the net heat W, "
                                  "temperature, emissivity, radiosity, irradiance and share to space)"),
                 args.vtu);
    return cmd;
}

void runExchange(const ExchangeArgs& args, const ProcessGroup& group) {
    Stopwatch clock;
    const Enforce enforceMode = parseEnforce(args.enforce);
    if (args.rays < args.batches)
        throw InputError("--rays " + std::to_string(args.rays) + " cannot be split into " +
                         std::to_string(args.batches) + " batches");
    ThermalDefaults defaults;
    if (args.defaultEmissivity > 0.0) {
        if (args.defaultEmissivity > 1.0) throw InputError("--default-emissivity must lie in (0, 1]");
        defaults.emissivity = args.defaultEmissivity;
    }
    if (args.defaultTemperature >= 0.0) defaults.temperature = args.defaultTemperature;
    if (!args.vtu.empty()) {
        checkOutputFile("--vtu", args.vtu);
        if (args.vtu == args.output || args.vtu == args.exchange)
            throw InputError("--vtu names the same file as another output: " + args.vtu);
    }

    Scene loaded = loadScene(args.input.scene);
    if (group.root()) printWarnings(loaded);  // every rank reads the same scene: one says so
    const std::uint64_t perBatch = args.rays / args.batches;
    std::vector<SurfaceCondition> conditions;
    // The properties are read from the mesh's surface names, before any device work.
    auto check = [&](const PreparedScene& meshed) {
        std::vector<std::string> names;
        for (const MeshSurface& s : meshed.mesh().surfaces) names.push_back(s.name);
        conditions = readThermalProperties(args.properties, names, defaults);
        if (group.root()) emitWarnings(smallReceivers(meshed.mesh(), "shoot", 0, perBatch * args.batches, true));
    };
    const PreparedScene scene(std::move(loaded), {args.input.patchSize, args.input.maxPatches},
                              DeviceChoice{deviceForRank(args.input.device, group.rank())}, check);

    ExchangeOptions options;
    options.raysPerSurface = args.rays;
    options.batches = args.batches;
    options.seed = args.input.seed;
    options.enforce = enforceMode;
    options.environmentTemperature = args.environmentTemperature;
    options.group = &group;
    const ExchangeEstimate estimate = estimateExchange(scene, conditions, options);
    const ViewFactorTable& table = estimate.table;
    const ExchangeSolution& solution = estimate.solution;
    const EnforceSummary& enforced = estimate.enforced;
    const std::size_t n = table.size();

    if (!group.root()) return;  // the others hold the same estimate; rank 0 writes it
    auto write = [&](std::ostream& out) { writeNetHeatCsv(out, estimate); };
    if (!args.exchange.empty()) {
        const std::vector<std::vector<double>> g = exchangeFactors(estimate.problem);
        writeFileAtomically(args.exchange, [&](std::ostream& out) {
            if (args.exchangeFormat == "mtx")
                writeExchangeMatrixMarket(out, estimate, g);
            else
                writeExchangeCsv(out, estimate, g);
        });
    }
    if (args.output.empty()) {
        write(std::cout);
        std::cout.flush();
    } else {
        writeFileAtomically(args.output, write);
    }
    if (!args.vtu.empty())
        writeFileAtomically(args.vtu, [&](std::ostream& out) { writeVtu(out, exchangeGrid(scene, estimate)); });

    double net = 0.0, largest = 0.0;
    for (double q : solution.netHeat) {
        net += q;
        largest = std::max(largest, std::fabs(q));
    }
    emitWarnings(exchangeWarnings(estimate, args.batches));
    if (enforceMode != Enforce::None)
        std::fprintf(stderr, "exchange: --enforce %s over %zu closed rows: largest view-factor change %.3g\n",
                     enforceName(enforceMode), enforced.closedRows, enforced.largestChange);
    std::fprintf(stderr,
                 "exchange: %zu surfaces, %llu rays per surface in %u batches; net heats sum to %.6g W, the "
                 "environment takes %.6g W (largest net heat %.6g W); %.2f s%s%s%s\n",
                 n, static_cast<unsigned long long>(estimate.raysPerSurface), args.batches, net, solution.toEnvironment,
                 largest, clock.seconds(),
                 group.size() > 1 ? (" on " + std::to_string(group.size()) + " ranks").c_str() : "",
                 args.output.empty() ? "" : ", wrote ", args.output.c_str());
    if (!args.vtu.empty()) std::fprintf(stderr, "exchange: wrote %s\n", args.vtu.c_str());
}

}  // namespace rad
