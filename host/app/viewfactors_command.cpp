#include <cstdio>
#include <iostream>

#include "app/commands.h"
#include "app/console.h"
#include "bvh/wide_bvh.h"
#include "cl/compute_context.h"
#include "cl/device_scene.h"
#include "formfactor/surface_view_factors.h"
#include "io/atomic_file.h"
#include "io/view_factor_csv.h"
#include "mesh/mesh.h"
#include "scene/gltf_loader.h"
#include "util/stopwatch.h"

namespace rad {

void runViewFactors(const ViewFactorArgs& args) {
    Stopwatch clock;
    const Scene scene = loadGltf(args.scene);
    printWarnings(scene);
    const Mesh mesh = buildMesh(scene, {args.patchSize, args.maxPatches});
    const WideBvh bvh = buildWideBvh(mesh.faces);
    auto compute = ComputeContext::open(args.device);
    const DeviceScene deviceScene(*compute, mesh, bvh);
    const SurfaceViewFactors factors =
        computeSurfaceViewFactors(*compute, mesh, deviceScene, {args.rays, args.seed});

    if (args.output.empty()) {
        writeViewFactorCsv(std::cout, factors);
        std::cout.flush();
    } else {
        writeFileAtomically(args.output, [&](std::ostream& out) { writeViewFactorCsv(out, factors); });
    }
    std::fprintf(stderr, "viewfactors: %zu surfaces, %zu patches, %llu rays per surface on %s, %.2f s%s%s\n",
                 factors.size(), mesh.patches.size(), static_cast<unsigned long long>(args.rays),
                 compute->description().name.c_str(), clock.seconds(), args.output.empty() ? "" : ", wrote ",
                 args.output.c_str());
}

}  // namespace rad
