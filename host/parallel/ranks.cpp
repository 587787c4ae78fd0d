#include "parallel/ranks.h"

#include <algorithm>
#include <cstdlib>

#ifdef RADIOSITY_WITH_MPI
#include <mpi.h>
#endif

#include "util/error.h"

namespace rad {
namespace {

// Whether a launcher started this process as one rank of several.
bool launchedByMpirun() {
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE"})
        if (std::getenv(name)) return true;
    return false;
}

}  // namespace

Ranks::Ranks(int* argc, char*** argv) {
#ifdef RADIOSITY_WITH_MPI
    if (!launchedByMpirun()) return;
    MPI_Init(argc, argv);
    initialised_ = true;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
#else
    (void)argc, (void)argv;
    (void)launchedByMpirun;
#endif
}

Ranks::~Ranks() {
#ifdef RADIOSITY_WITH_MPI
    if (initialised_) MPI_Finalize();
#endif
}

void Ranks::sum(std::vector<std::uint64_t>& values) const {
    if (size_ == 1 || values.empty()) return;
#ifdef RADIOSITY_WITH_MPI
    // In pieces of at most 2^27 words, so the count fits an int and no rank holds a second
    // copy of a large vector.
    constexpr std::size_t kPiece = std::size_t{1} << 27;
    for (std::size_t at = 0; at < values.size(); at += kPiece) {
        const int count = static_cast<int>(std::min(kPiece, values.size() - at));
        MPI_Allreduce(MPI_IN_PLACE, values.data() + at, count, MPI_UINT64_T, MPI_SUM, MPI_COMM_WORLD);
    }
#endif
}

std::vector<std::uint64_t> Ranks::allGather(const std::vector<std::uint64_t>& mine) const {
    if (size_ == 1) return mine;
#ifdef RADIOSITY_WITH_MPI
    const int count = static_cast<int>(mine.size());
    if (mine.size() > 0x7FFFFFFFu) throw RuntimeFailure("rank " + std::to_string(rank_) + ": too much to gather");
    std::vector<int> counts(static_cast<std::size_t>(size_)), offsets(static_cast<std::size_t>(size_));
    MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
    long long total = 0;
    for (int r = 0; r < size_; ++r) {
        offsets[static_cast<std::size_t>(r)] = static_cast<int>(total);
        total += counts[static_cast<std::size_t>(r)];
    }
    if (total > 0x7FFFFFFF) throw RuntimeFailure("the ranks' results are too large to gather in one call");
    std::vector<std::uint64_t> all(static_cast<std::size_t>(total));
    MPI_Allgatherv(mine.data(), count, MPI_UINT64_T, all.data(), counts.data(), offsets.data(), MPI_UINT64_T,
                   MPI_COMM_WORLD);
    return all;
#else
    return mine;
#endif
}

void Ranks::abort(int status) const {
#ifdef RADIOSITY_WITH_MPI
    if (initialised_ && size_ > 1) MPI_Abort(MPI_COMM_WORLD, status);
#endif
    std::exit(status);
}

}  // namespace rad
