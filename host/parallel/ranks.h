#pragma once
// The processes of one run (MPI ranks), or just this one. Under `mpirun -np N` every rank runs
// the same command on the same input; work is divided among them by rules that depend only on
// the work (surface s belongs to rank s mod N), and what each computed is gathered so every
// rank holds the same result, bitwise that of one process. Only rank 0 writes outputs and
// prints. MPI is initialised only when a launcher started the process (Open MPI's or PMIx's
// environment), so a plain run, the tests and the sanitizer build never touch it; a build
// without MPI (RADIOSITY_WITH_MPI undefined) is always one process.

#include <cstdint>
#include <string>
#include <vector>

#include "parallel/process_group.h"

namespace rad {

class Ranks : public ProcessGroup {
public:
    // Initialises MPI when launched by mpirun (and built with it); finalises it on destruction.
    Ranks(int* argc, char*** argv);
    ~Ranks();
    Ranks(const Ranks&) = delete;
    Ranks& operator=(const Ranks&) = delete;

    int rank() const override { return rank_; }
    int size() const override { return size_; }

    void sum(std::vector<std::uint64_t>& values) const override;
    std::vector<std::uint64_t> allGather(const std::vector<std::uint64_t>& mine) const override;

    // Ends every rank of the run with `status` (after this rank reported why): a rank that fails
    // must not leave the others waiting in a collective.
    [[noreturn]] void abort(int status) const;

private:
    int rank_ = 0, size_ = 1;
    bool initialised_ = false;
};

}  // namespace rad
