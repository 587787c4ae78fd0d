#include <cstdio>
#include <iostream>

#include "app/commands.h"
#include "app/console.h"
#include "app/reliability.h"
#include "formfactor/enforce.h"
#include "formfactor/patch_matrix.h"
#include "formfactor/surface_view_factors.h"
#include "formfactor/view_factor_table.h"
#include "io/atomic_file.h"
#include "io/view_factor_csv.h"
#include "mesh/mesh.h"
#include "prepared/prepared_scene.h"
#include "scene/gltf_loader.h"
#include "util/error.h"
#include "util/stopwatch.h"

namespace rad {

FormFactorOptions formFactorOptions(const MethodArgs& args, std::uint32_t seed) {
    FormFactorOptions o;
    o.method = parseMethod(args.method);
    o.raysPerPatch = args.raysPerPatch;
    o.hemicubeResolution = args.hemicubeResolution;
    o.hemicubeJitter = args.hemicubeJitter;
    o.shadowRays = args.shadowRays;
    o.seed = seed;
    o.maxMemory = args.maxMemory;
    return o;
}

void runViewFactors(const ViewFactorArgs& args) {
    Stopwatch clock;
    if (args.level != "surface" && args.level != "patch") throw InputError("--level " + args.level + ": use surface or patch");
    if (args.format != "csv" && args.format != "mtx") throw InputError("--format " + args.format + ": use csv or mtx");
    const Enforce enforceMode = parseEnforce(args.enforce);
    const FormFactorOptions options = formFactorOptions(args.method, args.seed);

    Scene loaded = loadGltf(args.scene);
    printWarnings(loaded);
    const PreparedScene scene(std::move(loaded), {args.patchSize, args.maxPatches}, DeviceChoice{args.device});
    const Mesh& mesh = scene.mesh();
    const bool surfaceRays = options.method == FormFactorMethod::Shoot && args.level == "surface";
    emitWarnings(samplingWarnings(mesh, args.method, surfaceRays ? args.rays : args.method.raysPerPatch, surfaceRays));

    ViewFactorTable table;
    std::string how;
    if (options.method == FormFactorMethod::Shoot && args.level == "surface") {
        table = surfaceTable(computeSurfaceViewFactors(scene, {args.rays, args.seed}));
        how = std::to_string(args.rays) + " rays per surface";
    } else {
        const PatchMatrix matrix = buildPatchMatrix(scene, options);
        const std::uint32_t rays = options.method == FormFactorMethod::Shoot ? options.raysPerPatch : 0;
        table = args.level == "patch" ? patchTable(mesh, matrix, rays) : surfaceTable(mesh, matrix, rays);
        how = std::string(methodName(options.method)) + " patch matrix";
        if (options.method == FormFactorMethod::Hemicube) {
            char sum[64];
            std::snprintf(sum, sizeof sum, ", delta form factors summed to %.6f before renormalising", matrix.weightSum);
            how += sum;
        }
    }
    const EnforceSummary enforced = enforce(table, enforceMode);

    auto write = [&](std::ostream& out) {
        if (args.format == "mtx") writeViewFactorMatrixMarket(out, table);
        else writeViewFactorCsv(out, table);
    };
    if (args.output.empty()) {
        write(std::cout);
        std::cout.flush();
    } else {
        writeFileAtomically(args.output, write);
    }
    if (enforceMode != Enforce::None)
        std::fprintf(stderr, "viewfactors: --enforce %s over %zu closed rows: largest change %.3g\n", enforceName(enforceMode),
                     enforced.closedRows, enforced.largestChange);
    std::fprintf(stderr, "viewfactors: %zu %s rows, %zu patches, %s, on %s, %.2f s%s%s\n", table.size(),
                 args.level.c_str(), mesh.patches.size(), how.c_str(), scene.compute().description().name.c_str(),
                 clock.seconds(), args.output.empty() ? "" : ", wrote ", args.output.c_str());
}

}  // namespace rad
