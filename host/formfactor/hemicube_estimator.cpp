// hemicube (Cohen and Greenberg 1985, the seed's method): a hemicube of R x R pixels over each
// shooter patch's centre (kernels/hemicube.cl); F_ij = the delta form factors of the pixels that
// see j, renormalised by the cube's sum. Point-sampled at the centre: aliasing on small
// receivers and errors in the near field (sampling_checks.h).

#include <algorithm>

#include "device/kernel_arguments.h"
#include "formfactor/estimator.h"
#include "formfactor/fixed_point_rows.h"
#include "formfactor/patch_matrix.h"
#include "formfactor/sampling_checks.h"
#include "prepared/prepared_scene.h"
#include "shared_math.h"
#include "util/error.h"
#include "util/sample_streams.h"

namespace rad {
namespace {

const OptionSpec kResolution =
    OptionSpec::count("--hemicube-res", "hemicube: pixels along the top face's edge (even)", 128, 2, 8192);
const OptionSpec kJitter =
    OptionSpec::flag("--hemicube-jitter", "hemicube: turn each cube by a random angle about the normal");

class HemicubeEstimator : public FormFactorEstimator {
public:
    HemicubeEstimator(const PreparedScene& scene, std::uint32_t resolution, bool jitter, std::uint32_t seed)
        : compute_(scene.compute()),
          kernel_(scene.device().kernel<HemicubeRowsArgs>("hemicube.cl", "hemicube_rows")),
          resolution_(resolution),
          jitter_(jitter),
          seed_(seed),
          patches_(scene.device().patchCount()) {}

    std::uint32_t batchSize() const override {
        const std::uint64_t byMemory = kRowBatchBytes / ((std::uint64_t{patches_} + 1) * 4);
        const std::uint64_t perShooter = 3ull * resolution_ * resolution_;
        const std::uint64_t byWork = std::max<std::uint64_t>(1, (1ull << 24) / perShooter);
        return static_cast<std::uint32_t>(std::clamp<std::uint64_t>(std::min(byMemory, byWork), 1, patches_));
    }

    FormFactorRows rows(const std::vector<std::uint32_t>& shooters) override {
        HemicubeRowsArgs args;
        args.resolution = resolution_;
        args.jitterSeed = jitter_ ? rad_hash2(seed_, kMatrixRowsStream) | 1u : 0u;
        const std::vector<rad_uint> values = runRowKernel(compute_, kernel_, args, shooters, patches_,
                                                          shooters.size() * 3 * resolution_ * resolution_);
        // The rows hold delta form factors whose sum differs from 1 by the cube's
        // discretisation: renormalise by that sum (missed pixels included).
        return decodeFixedPointRows(values, shooters.size(), patches_, true);
    }

    std::vector<std::pair<std::string, double>> reportParameters(const PatchMatrix& matrix) const override {
        return {{"hemicube_res", resolution_},
                {"hemicube_jitter", jitter_ ? 1 : 0},
                {"hemicube_weight_sum", matrix.weightSum}};
    }

    std::string note(const PatchMatrix& matrix) const override {
        char sum[64];
        std::snprintf(sum, sizeof sum, ", delta form factors summed to %.6f before renormalising", matrix.weightSum);
        return sum;
    }

private:
    ComputeContext& compute_;
    DeviceKernel<HemicubeRowsArgs> kernel_;
    std::uint32_t resolution_;
    bool jitter_;
    std::uint32_t seed_, patches_;
};

}  // namespace

FormFactorMethod hemicubeMethod() {
    return {"hemicube",
            "a hemicube of pixels over each patch's centre, sees the nearest patch per pixel",
            {kResolution, kJitter},
            [](const PreparedScene& scene, const OptionValues& values,
               std::uint32_t seed) -> std::unique_ptr<FormFactorEstimator> {
                const std::uint32_t resolution = values.count32(kResolution);
                if (resolution < 2 || resolution % 2 != 0)
                    throw InputError("--hemicube-res must be an even number of at least 2 (the sides are R x R/2)");
                return std::make_unique<HemicubeEstimator>(scene, resolution, values.flag(kJitter), seed);
            },
            [](const Mesh& mesh, const OptionValues& values) {
                std::vector<std::string> warnings =
                    smallReceivers(mesh, "hemicube", values.count32(kResolution), 0, false);
                for (std::string& w : nearField(mesh, "hemicube")) warnings.push_back(std::move(w));
                return warnings;
            }};
}

}  // namespace rad
