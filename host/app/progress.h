#pragma once
// Progress of a solve on stderr: a bar redrawn in place on a terminal, a plain line every few
// seconds otherwise (logs, CI).

#include <cstdint>

#include "solver/progressive_solver.h"

namespace rad {

class ProgressDisplay {
public:
    explicit ProgressDisplay(double tolerance);
    void update(const SolveProgress& p);
    void finish();  // ends the bar's line (the next update starts a new one)

private:
    double tolerance_;
    bool terminal_;
    double lastPrint_ = 0.0;
    bool drawn_ = false;
};

}  // namespace rad
