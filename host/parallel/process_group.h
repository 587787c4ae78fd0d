#pragma once
// The processes that share one run's work, as the library sees them: under `mpirun -np N`
// every rank runs the same command on the same input and divides the work by rules that depend
// only on the work (`divideByCost`), then combines what each computed with exact integer
// collectives, so every process holds bitwise what one process would have computed. The
// library takes a ProcessGroup and never MPI itself: `parallel/ranks.h` is the MPI one (in the
// program), `oneProcess()` the group of a plain run, of the tests and of the bench programs.
//
// Every collective must be called by every process of the group, in the same order, with
// vectors of the same length: callers keep their control flow the same on every process (no
// decision on a clock or a signal that only one process saw, unless it is agreed by
// `anyProcess` first).

#include <cstdint>
#include <string>
#include <vector>

namespace rad {

class ProcessGroup {
public:
    virtual ~ProcessGroup() = default;
    virtual int rank() const = 0;
    virtual int size() const = 0;
    bool root() const { return rank() == 0; }

    // Every process's `values` summed element by element, modulo 2^64 (as the device's 64-bit
    // fixed-point sums wrap), into every process's copy.
    virtual void sum(std::vector<std::uint64_t>& values) const = 0;
    // Every process's `mine`, concatenated in rank order, on every process.
    virtual std::vector<std::uint64_t> allGather(const std::vector<std::uint64_t>& mine) const = 0;
};

// The group of a run that is one process: sums and gathers return what they were given.
const ProcessGroup& oneProcess();

// Whether `mine` is true on any process: a decision taken from something only some processes
// may have seen (a signal, a clock), made the same everywhere.
bool anyProcess(const ProcessGroup& group, bool mine);

// Every process's text, in rank order (for reports: which device each rank used).
std::vector<std::string> gatherTexts(const ProcessGroup& group, const std::string& mine);

// Which process does each task: longest first (ties by index) to the process with the least
// work so far (ties to the lowest rank). Depends only on the costs and the number of
// processes, so every process computes the same division.
std::vector<std::uint32_t> divideByCost(const std::vector<std::uint64_t>& costs, int processes);

}  // namespace rad
