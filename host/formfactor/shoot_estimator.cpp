// shoot: stratified rays from each shooter patch (kernels/shoot.cl), F_ij = hits_j / rays.
// Unbiased, with the binomial error of its rays; misses receivers smaller than a ray resolves
// (sampling_checks.h).

#include <algorithm>

#include "formfactor/estimator.h"
#include "formfactor/patch_matrix.h"
#include "formfactor/ray_shooter.h"
#include "formfactor/sampling_checks.h"
#include "prepared/prepared_scene.h"
#include "shared_math.h"
#include "util/sample_streams.h"

namespace rad {
namespace {

const OptionSpec kRaysPerPatch = OptionSpec::count(
    "--rays-per-patch", "shoot: rays per patch when a whole patch matrix is built", 4096, 1, 4294967295.0);

class ShootEstimator : public FormFactorEstimator {
public:
    ShootEstimator(const PreparedScene& scene, std::uint32_t raysPerPatch, std::uint32_t seed)
        : compute_(scene.compute()),
          shooter_(scene.compute(), scene.device()),
          raysPerPatch_(raysPerPatch),
          seed_(seed),
          patches_(scene.device().patchCount()) {}

    std::uint32_t batchSize() const override {
        const std::uint64_t byMemory = kRowBatchBytes / (std::uint64_t{shooter_.columns()} * 4);
        const std::uint64_t byWork = std::max<std::uint64_t>(1, (1u << 22) / raysPerPatch_);
        return static_cast<std::uint32_t>(std::clamp<std::uint64_t>(std::min(byMemory, byWork), 1, patches_));
    }

    FormFactorRows rows(const std::vector<std::uint32_t>& shooters) override {
        std::vector<RayRequest> requests;
        for (std::uint32_t k = 0; k < shooters.size(); ++k) {
            RayRequest r;
            r.firstTriangle = shooters[k];
            r.rays = raysPerPatch_;
            r.scramble = rad_hash2(rad_hash2(seed_, kMatrixRowsStream), shooters[k]);
            r.row = k;
            requests.push_back(r);
        }
        const std::size_t count = shooters.size() * shooter_.columns();
        DeviceArray<rad_uint> counts = DeviceArray<rad_uint>::upload(compute_, std::vector<rad_uint>(count, 0),
                                                                     "hit counts", DeviceAccess::readWrite);
        const std::vector<Launch> launches = planLaunches(requests, RayShooter::kMaxRaysPerLaunch);
        shooter_.countHits(launches, counts);  // launches outlive the blocking read below
        const std::vector<rad_uint> c = counts.read();
        FormFactorRows batch;
        const double rays = raysPerPatch_;
        for (std::size_t k = 0; k < shooters.size(); ++k) {
            const rad_uint* row = c.data() + k * shooter_.columns();
            FormFactorRow entries;
            for (std::uint32_t j = 0; j < patches_; ++j)
                if (row[j] != 0) entries.emplace_back(j, static_cast<float>(row[j] / rays));
            batch.rows.push_back(std::move(entries));
            batch.missed.push_back(
                static_cast<float>((row[shooter_.escapedColumn()] + row[shooter_.blackColumn()]) / rays));
            batch.blackBack.push_back(static_cast<float>(row[shooter_.blackColumn()] / rays));
        }
        return batch;
    }

    std::uint32_t raysPerRow() const override { return raysPerPatch_; }

    std::vector<std::pair<std::string, double>> reportParameters(const PatchMatrix&) const override {
        return {{"rays_per_patch", raysPerPatch_}};
    }

private:
    ComputeContext& compute_;
    RayShooter shooter_;
    std::uint32_t raysPerPatch_, seed_, patches_;
};

}  // namespace

FormFactorMethod shootMethod() {
    return {"shoot",
            "rays from each patch, F_ij = the share that lands on j",
            {kRaysPerPatch},
            [](const PreparedScene& scene, const OptionValues& values,
               std::uint32_t seed) -> std::unique_ptr<FormFactorEstimator> {
                return std::make_unique<ShootEstimator>(scene, values.count32(kRaysPerPatch), seed);
            },
            [](const Mesh& mesh, const OptionValues& values) {
                return smallReceivers(mesh, "shoot", 0, values.count64(kRaysPerPatch), false);
            }};
}

}  // namespace rad
