#pragma once
// The whole patch-to-patch form-factor matrix, from any estimator (estimator.h): rows in
// batches of shooters, stored sparsely, refused with the figures as soon as the rows so far say
// it will not fit. Used by the matrix solvers and by patch-level view factors.

#include <cstdint>
#include <string>
#include <vector>

#include "formfactor/estimator.h"
#include "formfactor/sparse_matrix.h"
#include "parallel/process_group.h"
#include "util/options.h"

namespace rad {

class PreparedScene;

struct PatchMatrix {
    SparseMatrix F;                // F(i, j): the fraction of the power leaving patch i that reaches j
    std::vector<float> missed;     // per row: the fraction that reached no patch (escaped, or a black back)
    std::vector<float> blackBack;  // per row: the part of `missed` stopped on a black back (0 where not known)
    double weightSum = 0.0;        // hemicube: mean sum of a cube's delta form factors before renormalising; else 0
    std::uint32_t raysPerRow = 0;  // rays behind each row when entries are fractions of rays (shoot); else 0
};

// --max-memory: what the matrix (and the direct solver's dense system) may take.
extern const OptionSpec kMaxMemoryOption;

// Throws InputError when the matrix would exceed maxMemory (with the figure). `method` names
// the estimator in that message. Under several processes (`group`) the batches of rows are
// divided among them (batch b on process b mod N) and gathered, so every process ends with
// bitwise the matrix of one process (an estimator's rows depend only on their shooters).
PatchMatrix buildPatchMatrix(FormFactorEstimator& estimator, std::uint32_t patches, std::uint64_t maxMemory,
                             const std::string& method, const ProcessGroup& group = oneProcess());

// The same, with the estimator the registry makes for `method` from `values`.
PatchMatrix buildPatchMatrix(const PreparedScene& scene, const std::string& method, const OptionValues& values,
                             std::uint32_t seed);

}  // namespace rad
