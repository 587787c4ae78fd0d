#include "solver/solve_strategy.h"

#include "util/error.h"

namespace rad {

const std::vector<SolveStrategyEntry>& solveStrategies() {
    // One line per strategy; the first that takes the method and solver is used.
    static const std::vector<SolveStrategyEntry> strategies = {
        deviceProgressiveStrategy(),
        matrixStrategy(),
    };
    return strategies;
}

const SolveStrategyEntry& solveStrategyFor(const std::string& method, const std::string& solver) {
    for (const SolveStrategyEntry& s : solveStrategies())
        if (s.takes(method, solver)) return s;
    throw InputError("no solve strategy takes --method " + method + " with --solver " + solver);
}

std::unique_ptr<SolveStrategy> makeSolveStrategy(const SolveChoice& choice) {
    return solveStrategyFor(choice.method, choice.solver).create(choice);
}

}  // namespace rad
