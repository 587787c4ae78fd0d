#pragma once
// Form-factor estimators: one interface, one file per method, one registry entry each
// (docs/architecture.md, "How to add"). An estimator computes rows of the
// patch-to-patch form-factor matrix for a set of shooter patches; patch_matrix.h assembles the
// rows into the whole matrix under a memory limit. The registry (estimators.cpp) names each
// method, describes it, declares the options it reads and the checks that tell, before the
// work, where its results would be unreliable; the command line is made from it.
//
// Methods today: shoot (shoot_estimator.cpp), hemicube (hemicube_estimator.cpp), gather
// (gather_estimator.cpp).

#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "mesh/mesh.h"
#include "util/options.h"

namespace rad {

class PreparedScene;
struct PatchMatrix;

using FormFactorRow = std::vector<std::pair<std::uint32_t, float>>;  // (patch, F), ascending

// What one batch of rows may take on the device, as the estimators size their batches.
inline constexpr std::uint64_t kRowBatchBytes = 64ull << 20;

// Rows of a batch of shooters, in the order asked for.
struct FormFactorRows {
    std::vector<FormFactorRow> rows;
    std::vector<float> missed;  // per row: the fraction that reached no patch (escaped, or a black back)
    std::vector<float> blackBack;  // per row: the part of `missed` stopped on a black back (empty: not known)
    double weightSum = 0.0;     // hemicube: its cubes' delta form factors before renormalising, summed
};

class FormFactorEstimator {
public:
    virtual ~FormFactorEstimator() = default;

    // The most shooters one rows() call takes: bounded by the memory of the rows and the work
    // of one launch.
    virtual std::uint32_t batchSize() const = 0;

    // F(i, .) for every shooter patch i in `shooters`.
    virtual FormFactorRows rows(const std::vector<std::uint32_t>& shooters) = 0;

    // Rays behind each row, when the entries are fractions of rays (their binomial standard
    // errors follow); 0 when they are not.
    virtual std::uint32_t raysPerRow() const { return 0; }

    // For the report, after the matrix was built: the method's parameters and what it measured.
    virtual std::vector<std::pair<std::string, double>> reportParameters(const PatchMatrix& matrix) const = 0;

    // A clause for the user about the matrix, or "" (hemicube: the sum of its delta form factors).
    virtual std::string note(const PatchMatrix& matrix) const {
        (void)matrix;
        return "";
    }
};

struct FormFactorMethod {
    std::string name;         // --method NAME
    std::string description;  // one line, for --help
    std::vector<OptionSpec> options;
    // The estimator on `scene` with the options in `values` (defaults where not given) and the
    // user's seed. Throws InputError when an option's value cannot work.
    std::unique_ptr<FormFactorEstimator> (*create)(const PreparedScene& scene, const OptionValues& values,
                                                   std::uint32_t seed);
    // Warnings for stderr and the report, before the work: receivers too small for its
    // sampling, near fields it cannot resolve (sampling_checks.h).
    std::vector<std::string> (*reliability)(const Mesh& mesh, const OptionValues& values);
};

// The registry, in the order --help lists the methods.
const std::vector<FormFactorMethod>& formFactorMethods();
// The method of that name; InputError naming the choices otherwise.
const FormFactorMethod& formFactorMethod(const std::string& name);

// Each method's entry, defined in its own file.
FormFactorMethod shootMethod();
FormFactorMethod hemicubeMethod();
FormFactorMethod gatherMethod();

}  // namespace rad
