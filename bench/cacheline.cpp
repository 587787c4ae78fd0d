// How long it takes to hand one cache line back and forth between two threads: two threads
// spin on one atomic, each flipping it when it is its turn. One round trip moves the line
// twice between the cores. Nothing else runs, so this is the machine's own cost of sharing a
// line between the cores the two threads land on (on a VM: wherever the hypervisor puts its
// vCPUs), which is what shared atomic counters pay. Prints one line of CSV.
//
//   bench_cacheline [--round-trips N]

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>

int main(int argc, char** argv) {
    long trips = 200000;
    for (int i = 1; i < argc; ++i)
        if (std::string(argv[i]) == "--round-trips" && i + 1 < argc) trips = std::atol(argv[++i]);
    alignas(64) std::atomic<int> turn{0};
    auto player = [&](int me) {
        for (long k = 0; k < trips; ++k) {
            while (turn.load(std::memory_order_acquire) != me) {
            }
            turn.store(1 - me, std::memory_order_release);
        }
    };
    const auto start = std::chrono::steady_clock::now();
    std::thread other(player, 1);
    player(0);
    other.join();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("round_trips,ns_per_round_trip\n%ld,%.1f\n", trips, 1e9 * seconds / static_cast<double>(trips));
    return 0;
}
