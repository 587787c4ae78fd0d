#include "formfactor/patch_matrix.h"

#include <algorithm>
#include <numeric>

#include "prepared/prepared_scene.h"
#include "util/error.h"
#include "util/format.h"

namespace rad {

const OptionSpec kMaxMemoryOption =
    OptionSpec::size("--max-memory", "refuse a form-factor matrix (or direct solve) larger than this", "4G");

PatchMatrix buildPatchMatrix(FormFactorEstimator& estimator, std::uint32_t patches, std::uint64_t maxMemory,
                             const std::string& method) {
    PatchMatrix matrix;
    matrix.F.columns = patches;
    matrix.raysPerRow = estimator.raysPerRow();
    double weightSum = 0.0;
    // Where even a dense matrix would fit there is nothing to guard; otherwise small batches
    // let the projection below refuse early, before much work is spent.
    const double dense = 8.0 * patches * static_cast<double>(patches);
    std::uint32_t batch = estimator.batchSize();
    if (dense > static_cast<double>(maxMemory)) batch = std::min(batch, std::max(1u, patches / 32));
    for (std::uint32_t first = 0; first < patches; first += batch) {
        std::vector<std::uint32_t> shooters(std::min(batch, patches - first));
        std::iota(shooters.begin(), shooters.end(), first);
        FormFactorRows rows = estimator.rows(shooters);
        for (std::size_t k = 0; k < rows.rows.size(); ++k) {
            matrix.F.appendRow(rows.rows[k]);
            matrix.missed.push_back(rows.missed[k]);
        }
        weightSum += rows.weightSum;
        // Refuse as soon as the rows so far say the whole matrix will not fit.
        const std::uint32_t done = matrix.F.rows();
        const double projected = static_cast<double>(matrix.F.bytes()) * patches / done;
        if (projected > static_cast<double>(maxMemory))
            throw InputError("the " + method + " form-factor matrix of " + std::to_string(patches) +
                             " patches would need about " + byteSize(static_cast<std::uint64_t>(projected)) + " (" +
                             std::to_string(matrix.F.nonZeros()) + " non-zeros in the first " + std::to_string(done) +
                             " rows); --max-memory allows " + byteSize(maxMemory));
    }
    matrix.weightSum = weightSum / std::max(1u, patches);
    return matrix;
}

PatchMatrix buildPatchMatrix(const PreparedScene& scene, const std::string& method, const OptionValues& values,
                             std::uint32_t seed) {
    const auto estimator = formFactorMethod(method).create(scene, values, seed);
    return buildPatchMatrix(*estimator, static_cast<std::uint32_t>(scene.mesh().patches.size()),
                            values.count64(kMaxMemoryOption), method);
}

}  // namespace rad
