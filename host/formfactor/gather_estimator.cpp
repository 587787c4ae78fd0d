// gather (after Wallace, Elmquist and Haines 1989): for each receiver patch j, the closed-form
// point-to-polygon factor to the shooter at three interior points of j, times the fraction of
// shadow rays to the shooter that arrive (kernels/gather.cl); F_ij = F_ji A_j / A_i. No noise
// from ray counts, but point-sampled receivers in the near field (sampling_checks.h).

#include <algorithm>

#include "device/kernel_arguments.h"
#include "formfactor/estimator.h"
#include "formfactor/fixed_point_rows.h"
#include "formfactor/patch_matrix.h"
#include "formfactor/sampling_checks.h"
#include "prepared/prepared_scene.h"
#include "shared_math.h"
#include "util/sample_streams.h"

namespace rad {
namespace {

const OptionSpec kShadowRays =
    OptionSpec::count("--shadow-rays", "gather: shadow rays per receiver point", 16, 1, 65536);

class GatherEstimator : public FormFactorEstimator {
public:
    GatherEstimator(const PreparedScene& scene, std::uint32_t shadowRays, std::uint32_t seed)
        : compute_(scene.compute()),
          kernel_(scene.device().kernel<GatherRowsArgs>("gather.cl", "gather_rows")),
          shadowRays_(shadowRays),
          seed_(seed),
          patches_(scene.device().patchCount()) {}

    std::uint32_t batchSize() const override {
        const std::uint64_t byMemory = kRowBatchBytes / ((std::uint64_t{patches_} + 1) * 4);
        const std::uint64_t perShooter = std::uint64_t{patches_} * 3 * std::max(1u, shadowRays_);
        const std::uint64_t byWork = std::max<std::uint64_t>(1, (1ull << 24) / perShooter);
        return static_cast<std::uint32_t>(std::clamp<std::uint64_t>(std::min(byMemory, byWork), 1, patches_));
    }

    FormFactorRows rows(const std::vector<std::uint32_t>& shooters) override {
        GatherRowsArgs args;
        args.shadowRays = shadowRays_;
        args.seed = rad_hash2(seed_, kMatrixRowsStream);
        const std::vector<rad_uint> values =
            runRowKernel(compute_, kernel_, args, shooters, patches_, shooters.size() * patches_);
        // Form factors already; what they do not account for counts as missed.
        return decodeFixedPointRows(values, shooters.size(), patches_, false);
    }

    std::vector<std::pair<std::string, double>> reportParameters(const PatchMatrix&) const override {
        return {{"shadow_rays", shadowRays_}};
    }

private:
    ComputeContext& compute_;
    DeviceKernel<GatherRowsArgs> kernel_;
    std::uint32_t shadowRays_, seed_, patches_;
};

}  // namespace

FormFactorMethod gatherMethod() {
    return {"gather",
            "closed-form point-to-patch factors at three points of each receiver, times shadow-ray visibility",
            {kShadowRays},
            [](const PreparedScene& scene, const OptionValues& values,
               std::uint32_t seed) -> std::unique_ptr<FormFactorEstimator> {
                return std::make_unique<GatherEstimator>(scene, values.count32(kShadowRays), seed);
            },
            [](const Mesh& mesh, const OptionValues&) { return nearField(mesh, "gather"); }};
}

}  // namespace rad
