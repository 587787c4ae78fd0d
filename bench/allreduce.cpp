// What the progressive solve's one collective per batch costs on this machine: MPI_Allreduce
// (sum of unsigned 64-bit integers, in place) of elements x 3 words, the counts every batch's
// shots leave on the elements (solver/progressive_solver.h), for a range of element counts.
// Every rank starts each repeat after a barrier; rank 0 prints one CSV line per size with the
// median and the smallest time of the repeats. For the model of larger runs (bench/scaling
// --mpi) it also times, on rank 0 alone, the local work every batch adds whatever the network:
// adding one vector of the counts into another (the reduction's arithmetic) and copying one (the
// solver reads the counts from the device and writes the sums back: two copies on PoCL).
// Built only where Open MPI is installed.
//
//   mpirun -np N bench_allreduce [--elements 1000,10000,...] [--repeats R]

#include <mpi.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

int main(int argc, char** argv) {
    MPI_Init(&argc, &argv);
    int rank = 0, size = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    std::vector<long> elements = {1000, 10000, 100000, 1000000, 10000000};
    int repeats = 11;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--elements" && i + 1 < argc) {
            elements.clear();
            std::stringstream list(argv[++i]);
            for (std::string item; std::getline(list, item, ',');) elements.push_back(std::atol(item.c_str()));
        } else if (a == "--repeats" && i + 1 < argc) {
            repeats = std::max(1, std::atoi(argv[++i]));
        }
    }
    if (rank == 0) std::printf("ranks,elements,bytes,median_s,min_s,local_add_s,local_copy_s,repeats\n");
    for (long n : elements) {
        std::vector<std::uint64_t> counts(static_cast<std::size_t>(3 * n), static_cast<std::uint64_t>(rank + 1));
        std::vector<double> times;
        for (int r = 0; r < repeats + 1; ++r) {  // the first is a warm-up
            MPI_Barrier(MPI_COMM_WORLD);
            const double start = MPI_Wtime();
            MPI_Allreduce(MPI_IN_PLACE, counts.data(), static_cast<int>(counts.size()), MPI_UINT64_T, MPI_SUM,
                          MPI_COMM_WORLD);
            double took = MPI_Wtime() - start;
            // The slowest rank's time is the collective's.
            MPI_Allreduce(MPI_IN_PLACE, &took, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
            if (r > 0) times.push_back(took);
        }
        std::sort(times.begin(), times.end());
        double add = 0.0, copy = 0.0;
        if (rank == 0) {
            std::vector<std::uint64_t> other(counts.size(), 7), copied(counts.size());
            std::vector<double> adds, copies;
            for (int r = 0; r < repeats; ++r) {
                double start = MPI_Wtime();
                for (std::size_t i = 0; i < counts.size(); ++i) counts[i] += other[i];
                adds.push_back(MPI_Wtime() - start);
                start = MPI_Wtime();
                std::copy(counts.begin(), counts.end(), copied.begin());
                copies.push_back(MPI_Wtime() - start);
            }
            std::sort(adds.begin(), adds.end());
            std::sort(copies.begin(), copies.end());
            add = adds[adds.size() / 2];
            copy = copies[copies.size() / 2];
            volatile std::uint64_t keep = copied[counts.size() / 2];  // the work is used: not optimised away
            (void)keep;
        }
        if (rank == 0)
            std::printf("%d,%ld,%ld,%.6g,%.6g,%.6g,%.6g,%d\n", size, n, 24 * n, times[times.size() / 2], times.front(),
                        add, copy, repeats);
    }
    MPI_Finalize();
    return 0;
}
