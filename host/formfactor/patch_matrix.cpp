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

std::uint64_t bitsOf(double value) {
    std::uint64_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    return bits;
}
std::uint32_t bitsOf(float value) {
    std::uint32_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    return bits;
}
template <typename T, typename Bits>
T valueOf(Bits bits) {
    static_assert(sizeof(T) == sizeof(Bits), "bits and value of one size");
    T value;
    std::memcpy(&value, &bits, sizeof value);
    return value;
}

// Refuses, as soon as the rows so far say the whole matrix will not fit (SparseMatrix::bytes),
// with the figures. Fed the batches in order, so it refuses where one process would.
class MemoryGuard {
public:
    MemoryGuard(std::uint32_t patches, std::uint64_t maxMemory, const std::string& method)
        : patches_(patches), maxMemory_(maxMemory), method_(method) {}
    void add(std::uint64_t rows, std::uint64_t nonZeros) {
        if (rows == 0) return;
        rows_ += rows;
        nonZeros_ += nonZeros;
        const double bytes = 8.0 * static_cast<double>(rows_ + 1) + 8.0 * static_cast<double>(nonZeros_);
        const double projected = bytes * patches_ / static_cast<double>(rows_);
        if (projected > static_cast<double>(maxMemory_))
            throw InputError("the " + method_ + " form-factor matrix of " + std::to_string(patches_) +
                             " patches would need about " + byteSize(static_cast<std::uint64_t>(projected)) + " (" +
                             std::to_string(nonZeros_) + " non-zeros in the first " + std::to_string(rows_) +
                             " rows); --max-memory allows " + byteSize(maxMemory_));
    }

private:
    std::uint32_t patches_;
    std::uint64_t maxMemory_;
    std::string method_;
    std::uint64_t rows_ = 0, nonZeros_ = 0;
};

std::uint64_t nonZerosOf(const FormFactorRows& rows) {
    std::uint64_t n = 0;
    for (const FormFactorRow& row : rows.rows) n += row.size();
    return n;
}

// One batch of rows as words, for the gather: its index, its weight sum, its row count, then per
// row the entry count, the missed fraction, its black-back part and each entry as column << 32 |
// the value's bits.
void packBatch(std::uint64_t index, const FormFactorRows& rows, std::vector<std::uint64_t>& words) {
    words.push_back(index);
    words.push_back(bitsOf(rows.weightSum));
    words.push_back(rows.rows.size());
    for (std::size_t k = 0; k < rows.rows.size(); ++k) {
        words.push_back(rows.rows[k].size());
        words.push_back(bitsOf(rows.missed[k]));
        words.push_back(bitsOf(k < rows.blackBack.size() ? rows.blackBack[k] : 0.0f));
        for (const auto& [column, value] : rows.rows[k]) words.push_back(std::uint64_t{column} << 32 | bitsOf(value));
    }
}

// Where each batch starts in every process's batches gathered, checking their structure.
std::vector<std::size_t> batchOffsets(const std::vector<std::uint64_t>& words, std::size_t batches) {
    auto damaged = []() { return RuntimeFailure("the processes' form-factor rows arrived damaged"); };
    std::vector<std::size_t> offset(batches, words.size());
    for (std::size_t at = 0; at < words.size();) {
        if (at + 3 > words.size() || words[at] >= batches || offset[words[at]] != words.size()) throw damaged();
        offset[words[at]] = at;
        const std::uint64_t rows = words[at + 2];
        at += 3;
        for (std::uint64_t k = 0; k < rows; ++k) {
            if (at + 3 > words.size() || words[at] > words.size() - at - 3) throw damaged();
            at += 3 + words[at];
        }
    }
    for (std::size_t o : offset)
        if (o == words.size()) throw damaged();
    return offset;
}

// Appends the packed batch at `at` to the matrix; returns its weight sum.
double appendPacked(const std::vector<std::uint64_t>& words, std::size_t at, PatchMatrix& matrix) {
    const double weightSum = valueOf<double>(words[at + 1]);
    const std::uint64_t rows = words[at + 2];
    at += 3;
    for (std::uint64_t k = 0; k < rows; ++k) {
        const std::uint64_t entries = words[at];
        matrix.missed.push_back(valueOf<float>(static_cast<std::uint32_t>(words[at + 1])));
        matrix.blackBack.push_back(valueOf<float>(static_cast<std::uint32_t>(words[at + 2])));
        at += 3;
        for (std::uint64_t e = 0; e < entries; ++e, ++at) {
            matrix.F.column.push_back(static_cast<std::uint32_t>(words[at] >> 32));
            matrix.F.value.push_back(valueOf<float>(static_cast<std::uint32_t>(words[at])));
        }
        matrix.F.rowStart.push_back(matrix.F.value.size());
    }
    return weightSum;
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
    auto rowsOf = [&](std::size_t b) {
        const auto first = static_cast<std::uint32_t>(b * batch);
        std::vector<std::uint32_t> shooters(std::min(batch, patches - first));
        std::iota(shooters.begin(), shooters.end(), first);
        return estimator.rows(shooters);
    };
    MemoryGuard guard(patches, maxMemory, method);
    double weightSum = 0.0;  // summed in batch order, as one process sums it
    if (group.size() == 1) {
        for (std::size_t b = 0; b < batches; ++b) {
            const FormFactorRows rows = rowsOf(b);
            for (std::size_t k = 0; k < rows.rows.size(); ++k) {
                matrix.F.appendRow(rows.rows[k]);
                matrix.missed.push_back(rows.missed[k]);
                matrix.blackBack.push_back(k < rows.blackBack.size() ? rows.blackBack[k] : 0.0f);
            }
            weightSum += rows.weightSum;
            guard.add(rows.rows.size(), nonZerosOf(rows));
        }
    } else {
        // In rounds of one batch per process; after each round every process checks the
        // round's batches against the guard in batch order, so all refuse where one would.
        const auto processes = static_cast<std::size_t>(group.size()), rank = static_cast<std::size_t>(group.rank());
        std::vector<std::uint64_t> packed;
        for (std::size_t round = 0; round < batches; round += processes) {
            std::vector<std::uint64_t> counts(2, 0);
            if (round + rank < batches) {
                const FormFactorRows rows = rowsOf(round + rank);
                counts = {rows.rows.size(), nonZerosOf(rows)};
                packBatch(round + rank, rows, packed);
            }
            const std::vector<std::uint64_t> all = group.allGather(counts);
            for (std::size_t p = 0; p < processes; ++p) guard.add(all[2 * p], all[2 * p + 1]);
        }
        std::vector<std::uint64_t> words = group.allGather(packed);
        packed = std::vector<std::uint64_t>();  // freed before the matrix grows
        const std::vector<std::size_t> offset = batchOffsets(words, batches);
        for (std::size_t b = 0; b < batches; ++b) weightSum += appendPacked(words, offset[b], matrix);
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
