#include "formfactor/patch_matrix.h"

#include <algorithm>
#include <cstring>
#include <numeric>

#include "prepared/prepared_scene.h"
#include "util/error.h"
#include "util/format.h"

namespace rad {

const OptionSpec kMaxMemoryOption =
    OptionSpec::size("--max-memory", "refuse a form-factor matrix (or direct solve) larger than this", "4G");

namespace {

// One batch of rows as words, for the gather: its index, its weight sum, its row count, then per
// row the entry count, the missed fraction and each entry as column << 32 | the value's bits.
void packBatch(std::uint64_t index, const FormFactorRows& rows, std::vector<std::uint64_t>& words) {
    auto bitsOf = [](auto value) {
        std::uint64_t bits = 0;
        std::memcpy(&bits, &value, sizeof value);
        return bits;
    };
    words.push_back(index);
    words.push_back(bitsOf(rows.weightSum));
    words.push_back(rows.rows.size());
    for (std::size_t k = 0; k < rows.rows.size(); ++k) {
        words.push_back(rows.rows[k].size());
        words.push_back(bitsOf(rows.missed[k]));
        for (const auto& [column, value] : rows.rows[k]) words.push_back(std::uint64_t{column} << 32 | bitsOf(value));
    }
}

// Every process's batches, back in batch order.
std::vector<FormFactorRows> unpackBatches(const std::vector<std::uint64_t>& words, std::size_t batches) {
    std::vector<FormFactorRows> all(batches);
    auto need = [&](std::size_t at, std::size_t count) {
        if (at + count > words.size()) throw RuntimeFailure("the processes' form-factor rows arrived damaged");
    };
    for (std::size_t at = 0; at < words.size();) {
        need(at, 3);
        const std::uint64_t index = words[at];
        if (index >= batches) throw RuntimeFailure("the processes' form-factor rows arrived damaged");
        FormFactorRows& rows = all[index];
        std::memcpy(&rows.weightSum, &words[at + 1], sizeof rows.weightSum);
        const std::uint64_t count = words[at + 2];
        at += 3;
        for (std::uint64_t k = 0; k < count; ++k) {
            need(at, 2);
            const std::uint64_t entries = words[at];
            float missed;
            std::memcpy(&missed, &words[at + 1], sizeof missed);
            at += 2;
            need(at, entries);
            FormFactorRow row;
            row.reserve(entries);
            for (std::uint64_t e = 0; e < entries; ++e, ++at) {
                const auto bits = static_cast<std::uint32_t>(words[at]);
                float value;
                std::memcpy(&value, &bits, sizeof value);
                row.emplace_back(static_cast<std::uint32_t>(words[at] >> 32), value);
            }
            rows.rows.push_back(std::move(row));
            rows.missed.push_back(missed);
        }
    }
    return all;
}

}  // namespace

PatchMatrix buildPatchMatrix(FormFactorEstimator& estimator, std::uint32_t patches, std::uint64_t maxMemory,
                             const std::string& method, const ProcessGroup& group) {
    PatchMatrix matrix;
    matrix.F.columns = patches;
    matrix.raysPerRow = estimator.raysPerRow();
    // Where even a dense matrix would fit there is nothing to guard; otherwise small batches
    // let the projection below refuse early, before much work is spent.
    const double dense = 8.0 * patches * static_cast<double>(patches);
    std::uint32_t batch = estimator.batchSize();
    if (dense > static_cast<double>(maxMemory)) batch = std::min(batch, std::max(1u, patches / 32));
    const std::size_t batches = (std::size_t{patches} + batch - 1) / batch;
    const auto processes = static_cast<std::size_t>(group.size()), rank = static_cast<std::size_t>(group.rank());
    double weightSum = 0.0;  // summed in batch order, as one process sums it
    auto append = [&](const FormFactorRows& rows) {
        for (std::size_t k = 0; k < rows.rows.size(); ++k) {
            matrix.F.appendRow(rows.rows[k]);
            matrix.missed.push_back(rows.missed[k]);
        }
        weightSum += rows.weightSum;
    };
    std::vector<std::uint64_t> packed;  // several processes: this one's batches, for the gather
    std::uint64_t ownRows = 0, ownNonZeros = 0;
    for (std::size_t b = rank; b < batches; b += processes) {
        const std::uint32_t first = static_cast<std::uint32_t>(b * batch);
        std::vector<std::uint32_t> shooters(std::min(batch, patches - first));
        std::iota(shooters.begin(), shooters.end(), first);
        const FormFactorRows rows = estimator.rows(shooters);
        if (processes == 1)
            append(rows);
        else
            packBatch(b, rows, packed);
        // Refuse as soon as the rows so far say the whole matrix will not fit (SparseMatrix::bytes).
        ownRows += rows.rows.size();
        for (const FormFactorRow& row : rows.rows) ownNonZeros += row.size();
        const double bytes = 8.0 * static_cast<double>(ownRows + 1) + 8.0 * static_cast<double>(ownNonZeros);
        const double projected = bytes * patches / static_cast<double>(ownRows);
        if (projected > static_cast<double>(maxMemory))
            throw InputError("the " + method + " form-factor matrix of " + std::to_string(patches) +
                             " patches would need about " + byteSize(static_cast<std::uint64_t>(projected)) + " (" +
                             std::to_string(ownNonZeros) + " non-zeros in the first " + std::to_string(ownRows) +
                             " rows); --max-memory allows " + byteSize(maxMemory));
    }
    if (processes > 1)
        for (const FormFactorRows& rows : unpackBatches(group.allGather(packed), batches)) append(rows);
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
