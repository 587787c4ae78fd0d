#include "formfactor/view_factor_study.h"

#include <cstdio>

#include "formfactor/estimator.h"
#include "formfactor/patch_matrix.h"
#include "formfactor/sampling_checks.h"

namespace rad {

const OptionSpec kSurfaceRaysOption = OptionSpec::count(
    "--rays", "rays cast from each surface in all, spread over it by area", 1'000'000, 1, 4294967295.0);
const OptionSpec kTargetErrorOption = OptionSpec::positive(
    "--target-error",
    "add rays per surface until every factor's standard error (the binomial bound) is at most this; --rays is "
    "then the first round's rays (default 10000)");
const OptionSpec kMaxRaysOption =
    OptionSpec::count("--max-rays", "with --target-error: the most rays per surface to cast", 1e9, 1, 1e13);

bool shootsFromSurfaces(const ViewFactorRequest& request) {
    return request.method == "shoot" && request.level == "surface";
}

std::vector<OptionSpec> viewFactorOptionsUsed(const ViewFactorRequest& request) {
    if (shootsFromSurfaces(request))
        return {kSurfaceRaysOption, kTargetErrorOption, kMaxRaysOption};  // the matrix's options go unused
    std::vector<OptionSpec> used = formFactorMethod(request.method).options;
    used.push_back(kMaxMemoryOption);
    return used;
}

std::vector<std::string> viewFactorChecks(const Mesh& mesh, const ViewFactorRequest& request) {
    if (shootsFromSurfaces(request))
        return smallReceivers(mesh, "shoot", 0, request.values.count64(kSurfaceRaysOption), true);
    return formFactorMethod(request.method).reliability(mesh, request.values);
}

std::vector<std::string> blackBackWarnings(const SurfaceViewFactors& factors) {
    std::vector<double> shares;
    for (std::size_t i = 0; i < factors.size(); ++i)
        shares.push_back(factors.raysPerSurface > 0 ? static_cast<double>(factors.blackBack[i]) /
                                                          static_cast<double>(factors.raysPerSurface)
                                                    : 0.0);
    return blackBackWarnings(factors.names, shares,
                             "they count toward no surface, so each such row sums to that much less");
}

std::vector<std::string> blackBackWarnings(const Mesh& mesh, const PatchMatrix& matrix) {
    if (matrix.raysPerRow == 0 || matrix.blackBack.size() != mesh.patches.size()) return {};  // not counted
    // Per surface side, as the surface rows count it: its patches' shares weighted by area.
    std::vector<std::string> names;
    std::vector<double> shares;
    for (const MeshSurface& s : mesh.surfaces) {
        double share = 0.0;
        for (std::uint32_t k = 0; k < s.patchCount; ++k)
            share += mesh.patches[s.firstPatch + k].area / s.area * matrix.blackBack[s.firstPatch + k];
        names.push_back(s.name);
        shares.push_back(share);
    }
    return blackBackWarnings(names, shares,
                             "they count toward no patch, so its patches' rows sum to that much less (the "
                             "area-weighted mean)");
}

ViewFactorStudy computeViewFactorStudy(const PreparedScene& scene, const ViewFactorRequest& request,
                                       const ProcessGroup& group) {
    ViewFactorStudy study;
    const OptionValues& values = request.values;
    if (shootsFromSurfaces(request)) {
        const std::uint64_t rays = values.count64(kSurfaceRaysOption);
        const double target = values.number(kTargetErrorOption);
        if (target > 0.0) {
            const std::uint64_t first = values.given(kSurfaceRaysOption.name) ? rays : 10'000;
            const TargetErrorEstimate estimate = computeSurfaceViewFactorsToError(
                scene, target, request.seed, first, values.count64(kMaxRaysOption), group);
            study.table = surfaceTable(estimate.factors);
            study.warnings = blackBackWarnings(estimate.factors);
            char text[200];
            std::snprintf(text, sizeof text,
                          "%llu rays per surface in %d rounds, largest standard error %.3g (before --enforce)",
                          static_cast<unsigned long long>(estimate.factors.raysPerSurface), estimate.rounds,
                          estimate.largestError);
            study.how = text;
            if (!estimate.reached) {
                std::snprintf(text, sizeof text,
                              "--target-error %g not reached within --max-rays %llu: the largest standard error (before --enforce) is "
                              "%.3g",
                              target, static_cast<unsigned long long>(values.count64(kMaxRaysOption)),
                              estimate.largestError);
                study.warnings.push_back(text);
            }
        } else {
            const SurfaceViewFactors factors =
                computeSurfaceViewFactors(scene, ViewFactorOptions{rays, request.seed}, group);
            study.table = surfaceTable(factors);
            study.warnings = blackBackWarnings(factors);
            study.how = std::to_string(rays) + " rays per surface";
        }
    } else {
        const FormFactorMethod& method = formFactorMethod(request.method);
        const Mesh& mesh = scene.mesh();
        const auto estimator = method.create(scene, values, request.seed);
        const PatchMatrix matrix = buildPatchMatrix(*estimator, static_cast<std::uint32_t>(mesh.patches.size()),
                                                    values.count64(kMaxMemoryOption), method.name, group);
        study.table = request.level == "patch" ? patchTable(mesh, matrix) : surfaceTable(mesh, matrix);
        study.warnings = blackBackWarnings(mesh, matrix);
        study.how = method.name + " patch matrix" + estimator->note(matrix);
    }
    return study;
}

}  // namespace rad
