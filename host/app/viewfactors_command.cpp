// radiosity viewfactors: surface-to-surface (or patch-to-patch) view factors, as CSV or Matrix
// Market. At the surface level with --method shoot, rays leave whole surfaces (--rays each);
// otherwise the patch matrix of the chosen estimator (formfactor/estimator.h) is summed up.

#include <cstdio>
#include <filesystem>
#include <iostream>

#include <CLI/CLI.hpp>

#include "app/commands.h"
#include "app/console.h"
#include "formfactor/enforce.h"
#include "formfactor/estimator.h"
#include "formfactor/patch_matrix.h"
#include "formfactor/sampling_checks.h"
#include "formfactor/surface_view_factors.h"
#include "formfactor/view_factor_study.h"
#include "formfactor/view_factor_table.h"
#include "io/atomic_file.h"
#include "io/patch_geometry_csv.h"
#include "io/view_factor_csv.h"
#include "parallel/ranks.h"
#include "prepared/prepared_scene.h"
#include "scene/scene_files.h"
#include "util/error.h"
#include "util/stopwatch.h"

namespace rad {
namespace {

ViewFactorRequest viewFactorRequest(const ViewFactorArgs& args) {
    ViewFactorRequest request;
    request.method = args.method;
    request.level = args.level;
    request.seed = args.input.seed;
    request.values = args.values;
    return request;
}

}  // namespace

CLI::App* addViewFactorsCommand(CLI::App& app, ViewFactorArgs& args) {
    CLI::App* cmd =
        app.add_subcommand("viewfactors", "Surface-to-surface view factors by ray shooting, as CSV: from,to,F,stderr.");
    args.declared = std::make_unique<DeclaredOptions>(cmd, &args.values);
    DeclaredOptions& options = *args.declared;
    addSceneInputOptions(options, args.input);
    options.add({kSurfaceRaysOption, kTargetErrorOption, kMaxRaysOption}, "--method shoot at --level surface");
    options.bind(OptionSpec::text("--output", "write the CSV to this file instead of standard output"), args.output);
    std::vector<std::string> methods;
    std::string about = "form factors by:";
    for (const FormFactorMethod& m : formFactorMethods()) {
        methods.push_back(m.name);
        about += std::string(methods.size() > 1 ? ";" : "") + " " + m.name + " (" + m.description + ")";
        // shoot's matrix options matter only for patch matrices: at the surface level it shoots
        // from whole surfaces.
        options.add(m.options, "--method " + m.name + (m.name == "shoot" ? " at --level patch" : ""));
    }
    options.bind(OptionSpec::choice("--method", about, "shoot", methods), args.method);
    options.add({kMaxMemoryOption}, "patch matrices (--level patch, or a --method other than shoot)");
    options.bind(OptionSpec::choice("--level", "surface-to-surface or patch-to-patch factors", "surface",
                                    {"surface", "patch"}),
                 args.level);
    options.bind(OptionSpec::choice("--format", "csv (from,to,F,stderr) or mtx (Matrix Market)", "csv", {"csv", "mtx"}),
                 args.format);
    options.bind(OptionSpec::text("--patches",
                                  "with --level patch: write where each patch is to this CSV (patch, surface, area, "
                                  "centroid, normal, corners, in the scene's coordinates in metres)"),
                 args.patches);
    options.bind(OptionSpec::text("--to-space",
                                  "also write, per row, the share that left the scene to this CSV (from,area,to_space,"
                                  "stderr: 1 - the row's sum before --enforce, rays stopped on a single-sided face's "
                                  "black back included)"),
                 args.toSpace);
    options.bind(OptionSpec::choice("--enforce", enforceHelp(), enforceName(kDefaultEnforce),
                                    {"none", "reciprocity", "closure", "both"}),
                 args.enforce);
    return cmd;
}

void runViewFactors(const ViewFactorArgs& args, const Ranks& ranks) {
    Stopwatch clock;
    const ViewFactorRequest request = viewFactorRequest(args);
    args.declared->refuseUnused(viewFactorOptionsUsed(request), "--method " + args.method + " at --level " + args.level);
    const Enforce enforceMode = parseEnforce(args.enforce);
    if (!args.patches.empty()) {
        if (args.level != "patch") throw InputError("--patches describes the rows of --level patch; add --level patch");
        if (args.patches == args.output) throw InputError("--patches and --output name the same file: " + args.patches);
        const std::filesystem::path folder = std::filesystem::path(args.patches).parent_path();
        std::error_code ec;
        if (!folder.empty() && !std::filesystem::is_directory(folder, ec))
            throw InputError("--patches " + args.patches + ": its folder does not exist");
    }

    if (!args.toSpace.empty()) {
        checkOutputFile("--to-space", args.toSpace);
        if (args.toSpace == args.output || args.toSpace == args.patches)
            throw InputError("--to-space names the same file as another output: " + args.toSpace);
    }

    Scene loaded = loadScene(args.input.scene);
    if (ranks.root()) printWarnings(loaded);  // every rank reads the same scene: one says so
    auto warn = [&](const PreparedScene& meshed) {  // from the mesh alone, before the device work
        if (ranks.root()) emitWarnings(viewFactorChecks(meshed.mesh(), request));
    };
    const PreparedScene scene(std::move(loaded), {args.input.patchSize, args.input.maxPatches},
                              DeviceChoice{deviceForRank(args.input.device, ranks.rank())}, warn);
    const Mesh& mesh = scene.mesh();

    ViewFactorStudy study = computeViewFactorStudy(scene, request, ranks);
    if (ranks.root()) emitWarnings(study.warnings);
    ViewFactorTable& table = study.table;
    std::string& how = study.how;
    if (ranks.size() > 1) how += " from " + std::to_string(ranks.size()) + " ranks";
    const SpaceShares space = spaceShares(table);  // before the correction closes rows
    const EnforceSummary enforced = enforce(table, enforceMode);

    if (!ranks.root()) return;  // the others hold the same table; rank 0 writes it
    auto write = [&](std::ostream& out) {
        if (args.format == "mtx")
            writeViewFactorMatrixMarket(out, table);
        else
            writeViewFactorCsv(out, table);
    };
    if (args.output.empty()) {
        write(std::cout);
        std::cout.flush();
    } else {
        writeFileAtomically(args.output, write);
    }
    if (!args.patches.empty())
        writeFileAtomically(args.patches,
                            [&](std::ostream& out) { writePatchGeometryCsv(out, mesh, scene.scene().origin); });
    if (!args.toSpace.empty())
        writeFileAtomically(args.toSpace, [&](std::ostream& out) { writeSpaceSharesCsv(out, table, space); });
    std::size_t open = 0, widest = 0;
    for (std::size_t i = 0; i < space.share.size(); ++i) {
        open += space.share[i] > 1e-3;
        if (space.share[i] > space.share[widest]) widest = i;
    }
    if (open > 0)
        std::fprintf(stderr, "viewfactors: %zu open rows lose to space up to %.3g ('%s')%s\n", open,
                     space.share[widest], table.names[widest].c_str(),
                     args.toSpace.empty() ? "; --to-space FILE writes every row's share" : "");
    if (enforceMode != Enforce::None)
        std::fprintf(stderr, "viewfactors: --enforce %s over %zu closed rows: largest change %.3g\n",
                     enforceName(enforceMode), enforced.closedRows, enforced.largestChange);
    std::fprintf(stderr, "viewfactors: %zu %s rows, %zu patches, %s, on %s, %.2f s%s%s\n", table.size(),
                 args.level.c_str(), mesh.patches.size(), how.c_str(), scene.compute().description().name.c_str(),
                 clock.seconds(), args.output.empty() ? "" : ", wrote ", args.output.c_str());
}

}  // namespace rad
