// The registries the command line is made from: form-factor methods, matrix solvers and solve
// strategies. Every method with every solver has exactly one strategy; each strategy reads the
// options of what it runs and no others; options that cannot work are refused before any work.

#include <algorithm>
#include <set>

#include <gtest/gtest.h>

#include "formfactor/estimator.h"
#include "formfactor/patch_matrix.h"
#include "solver/matrix_solvers.h"
#include "solver/progressive_options.h"
#include "solver/solve_strategy.h"
#include "util/error.h"

namespace rad {
namespace {

bool reads(const SolveStrategy& strategy, const std::string& option) {
    const auto options = strategy.options();
    return std::any_of(options.begin(), options.end(), [&](const OptionSpec& s) { return s.name == option; });
}

void expectWellFormed(const std::string& name, const std::string& description, const std::vector<OptionSpec>& options) {
    EXPECT_FALSE(name.empty());
    EXPECT_FALSE(description.empty()) << name;
    std::set<std::string> seen;
    for (const OptionSpec& o : options) {
        EXPECT_EQ(o.name.rfind("--", 0), 0u) << name << ": " << o.name;
        EXPECT_FALSE(o.help.empty()) << name << ": " << o.name;
        EXPECT_TRUE(seen.insert(o.name).second) << name << " declares " << o.name << " twice";
        if (o.kind == OptionKind::Count) EXPECT_TRUE(o.defaultValue >= o.min && o.defaultValue <= o.max) << o.name;
    }
}

TEST(Registries, EntriesAreNamedDescribedAndDeclareTheirOptionsOnce) {
    std::set<std::string> names;
    for (const FormFactorMethod& m : formFactorMethods()) {
        expectWellFormed(m.name, m.description, m.options);
        EXPECT_TRUE(names.insert(m.name).second) << m.name;
        EXPECT_NE(m.create, nullptr) << m.name;
        EXPECT_NE(m.reliability, nullptr) << m.name;
    }
    for (const MatrixSolverEntry& s : matrixSolvers()) expectWellFormed(s.name, s.description, s.options);
    for (const SolveStrategyEntry& s : solveStrategies()) expectWellFormed(s.name, s.description, s.options);
}

TEST(Registries, UnknownNamesAreRefusedWithTheChoices) {
    try {
        formFactorMethod("radiance");
        FAIL() << "an unknown method was found";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("shoot, hemicube, gather"), std::string::npos) << e.what();
    }
    EXPECT_THROW(matrixSolverNamed("conjugate-gradient"), InputError);
}

TEST(Registries, EveryMethodWithEverySolverHasAStrategy) {
    for (const FormFactorMethod& m : formFactorMethods())
        for (const MatrixSolverEntry& s : matrixSolvers()) {
            const SolveStrategyEntry& chosen = solveStrategyFor(m.name, s.name);
            EXPECT_EQ(chosen.name, m.name == "shoot" && s.name == "progressive" ? "device-progressive" : "matrix")
                << m.name << " " << s.name;
        }
}

TEST(Registries, StrategiesReadTheOptionsOfWhatTheyRunAndNoOthers) {
    const auto device = makeSolveStrategy({"shoot", "progressive", {}, 1});
    for (const char* o : {"--rays", "--tolerance", "--adaptive", "--element-size", "--checkpoint"})
        EXPECT_TRUE(reads(*device, o)) << o;
    for (const char* o : {"--rays-per-patch", "--max-memory", "--bounces", "--hemicube-res"})
        EXPECT_FALSE(reads(*device, o)) << o;

    const auto jacobi = makeSolveStrategy({"hemicube", "jacobi", {}, 1});
    for (const char* o : {"--hemicube-res", "--hemicube-jitter", "--bounces", "--residual", "--max-memory"})
        EXPECT_TRUE(reads(*jacobi, o)) << o;
    for (const char* o : {"--rays", "--tolerance", "--shadow-rays", "--rays-per-patch", "--adaptive"})
        EXPECT_FALSE(reads(*jacobi, o)) << o;

    const auto gatherProgressive = makeSolveStrategy({"gather", "progressive", {}, 1});
    EXPECT_TRUE(reads(*gatherProgressive, "--tolerance"));
    EXPECT_TRUE(reads(*gatherProgressive, "--shadow-rays"));
    EXPECT_FALSE(reads(*gatherProgressive, "--residual"));
}

TEST(Registries, OptionsThatCannotWorkAreRefusedBeforeAnyWork) {
    // --tolerance 0 with nothing else to stop the device's solver.
    EXPECT_THROW(makeSolveStrategy({"shoot", "progressive", {{"--tolerance", 0.0}}, 1}), InputError);
    EXPECT_NO_THROW(makeSolveStrategy({"shoot", "progressive", {{"--tolerance", 0.0}, {"--max-shots", 10}}, 1}));
    // Adaptive refinement does not checkpoint yet.
    OptionValues adaptive{{"--adaptive", 1}};
    adaptive.setText("--checkpoint", "state.ckpt");
    EXPECT_THROW(makeSolveStrategy({"shoot", "progressive", adaptive, 1}), InputError);
    // The progressive solver on a matrix needs a tolerance to stop at.
    EXPECT_THROW(makeSolveStrategy({"hemicube", "progressive", {{"--tolerance", 0.0}}, 1}), InputError);
}

const OptionSpec& declared(const std::vector<OptionSpec>& options, const std::string& name) {
    for (const OptionSpec& o : options)
        if (o.name == name) return o;
    throw std::runtime_error("no option " + name);
}

TEST(Registries, UnsetOptionsReadAsTheirDeclaredDefaults) {
    const OptionValues none;
    // The defaults the guide documents (docs/guide/methods.md, solve.md, refinement.md).
    EXPECT_EQ(none.count32(declared(formFactorMethod("shoot").options, "--rays-per-patch")), 4096u);
    EXPECT_EQ(none.count32(declared(formFactorMethod("hemicube").options, "--hemicube-res")), 128u);
    EXPECT_FALSE(none.flag(declared(formFactorMethod("hemicube").options, "--hemicube-jitter")));
    EXPECT_EQ(none.count32(declared(formFactorMethod("gather").options, "--shadow-rays")), 16u);
    EXPECT_EQ(none.count32(kBouncesOption), 0u);
    EXPECT_EQ(none.number(kResidualOption), 1e-6);
    EXPECT_EQ(none.count32(kMinRaysOption), 128u);
    EXPECT_EQ(none.number(kCheckpointEveryOption), 60.0);
    EXPECT_EQ(none.count64(kMaxElementsOption), 4'000'000u);
    EXPECT_EQ(none.count32(kRefinePassesOption), 4u);
    EXPECT_EQ(none.number(kRefineThresholdOption), 0.05);
    EXPECT_EQ(none.count64(kRaysOption), 16'000'000u);
    EXPECT_EQ(none.number(kToleranceOption), 1e-3);
    EXPECT_FALSE(none.flag(kAdaptiveOption));
    EXPECT_EQ(none.count64(kMaxMemoryOption), 4ull << 30);
    const OptionValues given{{"--rays", 1e5}};
    EXPECT_EQ(given.count64(kRaysOption), 100'000u);
    double bytes = 0.0;
    EXPECT_TRUE(parseSize("512M", bytes));
    EXPECT_EQ(bytes, 512.0 * 1048576.0);
    EXPECT_FALSE(parseSize("12 parsecs", bytes));
}

}  // namespace
}  // namespace rad
