// The library's side of running on several processes (parallel/process_group.h), without MPI:
// the division of a batch's work, the texts the report gathers, and the patch matrix built by
// processes that each compute some batches of rows, here played by threads.

#include <gtest/gtest.h>

#include <condition_variable>
#include <cstring>
#include <mutex>
#include <numeric>
#include <thread>

#include "formfactor/patch_matrix.h"
#include "parallel/process_group.h"

namespace rad {
namespace {

TEST(ProcessGroup, DivideByCostGivesTheLongestFirstToTheLeastLoaded) {
    // 9 to 0; 7 to 1 (0 holds 9); 5 to 1 (7 < 9); 4 to 0 (9 < 12); 1 to 1 (12 < 13).
    const std::vector<std::uint64_t> cost = {4, 9, 1, 7, 5};
    const std::vector<std::uint32_t> owner = divideByCost(cost, 2);
    EXPECT_EQ(owner, (std::vector<std::uint32_t>{0, 0, 1, 1, 1}));
    // Ties: the earlier task first, to the lowest rank.
    EXPECT_EQ(divideByCost({3, 3, 3}, 3), (std::vector<std::uint32_t>{0, 1, 2}));
    EXPECT_EQ(divideByCost({3, 3, 3}, 1), (std::vector<std::uint32_t>{0, 0, 0}));
    EXPECT_TRUE(divideByCost({}, 4).empty());
}

TEST(ProcessGroup, DivideByCostBalancesWithinTheLargestTask) {
    // Greedy's bound: no process holds more than the mean plus the largest task.
    std::vector<std::uint64_t> cost;
    std::uint64_t state = 12345;
    for (int k = 0; k < 1000; ++k) {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        cost.push_back(128 + (state >> 40) % 100000);
    }
    for (int processes : {2, 3, 7, 64}) {
        const std::vector<std::uint32_t> owner = divideByCost(cost, processes);
        std::vector<std::uint64_t> load(static_cast<std::size_t>(processes), 0);
        for (std::size_t k = 0; k < cost.size(); ++k) {
            ASSERT_LT(owner[k], static_cast<std::uint32_t>(processes));
            load[owner[k]] += cost[k];
        }
        const double total = std::accumulate(cost.begin(), cost.end(), 0.0);
        const double largest = static_cast<double>(*std::max_element(cost.begin(), cost.end()));
        for (std::uint64_t l : load) EXPECT_LE(static_cast<double>(l), total / processes + largest) << processes;
    }
}

TEST(ProcessGroup, OneProcessGathersAndSumsWhatItWasGiven) {
    const ProcessGroup& one = oneProcess();
    EXPECT_EQ(one.size(), 1);
    EXPECT_TRUE(one.root());
    std::vector<std::uint64_t> values = {1, 2, ~0ull};
    one.sum(values);
    EXPECT_EQ(values, (std::vector<std::uint64_t>{1, 2, ~0ull}));
    EXPECT_FALSE(anyProcess(one, false));
    EXPECT_TRUE(anyProcess(one, true));
    EXPECT_EQ(gatherTexts(one, "PoCL: cpu"), (std::vector<std::string>{"PoCL: cpu"}));
    EXPECT_EQ(gatherTexts(one, ""), (std::vector<std::string>{""}));
}

// Processes played by threads: collectives meet at a barrier over shared slots.
class ThreadTeam {
public:
    explicit ThreadTeam(int size) : slots_(static_cast<std::size_t>(size)) {}
    int size() const { return static_cast<int>(slots_.size()); }

    class Member : public ProcessGroup {
    public:
        Member(ThreadTeam& team, int rank) : team_(team), rank_(rank) {}
        int rank() const override { return rank_; }
        int size() const override { return team_.size(); }
        void sum(std::vector<std::uint64_t>& values) const override {
            const std::vector<std::uint64_t> all = allGather(values);
            for (std::size_t i = 0; i < values.size(); ++i) {
                values[i] = 0;
                for (int r = 0; r < size(); ++r) values[i] += all[static_cast<std::size_t>(r) * values.size() + i];
            }
        }
        std::vector<std::uint64_t> allGather(const std::vector<std::uint64_t>& mine) const override {
            team_.slots_[static_cast<std::size_t>(rank_)] = mine;
            team_.barrier();
            std::vector<std::uint64_t> all;
            for (const auto& slot : team_.slots_) all.insert(all.end(), slot.begin(), slot.end());
            team_.barrier();  // nobody overwrites a slot before everyone has read it
            return all;
        }

    private:
        ThreadTeam& team_;
        int rank_;
    };

private:
    void barrier() {
        std::unique_lock<std::mutex> lock(mutex_);
        const std::uint64_t generation = generation_;
        if (++waiting_ == size()) {
            waiting_ = 0;
            ++generation_;
            arrived_.notify_all();
        } else {
            arrived_.wait(lock, [&] { return generation_ != generation; });
        }
    }
    std::vector<std::vector<std::uint64_t>> slots_;
    std::mutex mutex_;
    std::condition_variable arrived_;
    int waiting_ = 0;
    std::uint64_t generation_ = 0;
};

// Rows that depend only on their shooter, in uneven batches, with a weight sum per batch whose
// floating-point total depends on the order it is summed in.
class MadeUpRows : public FormFactorEstimator {
public:
    std::uint32_t batchSize() const override { return 5; }
    FormFactorRows rows(const std::vector<std::uint32_t>& shooters) override {
        FormFactorRows out;
        for (std::uint32_t i : shooters) {
            FormFactorRow row;
            for (std::uint32_t j = 0; j < 23; ++j)
                if ((i + 2 * j) % 3 == 0) row.emplace_back(j, 1.0f / static_cast<float>(1 + i + j * j));
            out.rows.push_back(row);
            out.missed.push_back(0.1f + 0.01f * static_cast<float>(i));
            out.weightSum += 1.0 / (3.0 + i);
        }
        return out;
    }
    std::vector<std::pair<std::string, double>> reportParameters(const PatchMatrix&) const override { return {}; }
};

TEST(ProcessGroup, PatchMatrixRowsFromSeveralProcessesAreOneProcesssBitwise) {
    MadeUpRows estimator;
    const PatchMatrix one = buildPatchMatrix(estimator, 23, 1ull << 30, "made-up");
    for (int size : {2, 3, 6}) {
        ThreadTeam team(size);
        std::vector<PatchMatrix> built(static_cast<std::size_t>(size));
        std::vector<std::thread> threads;
        for (int r = 0; r < size; ++r)
            threads.emplace_back([&, r] {
                const ThreadTeam::Member member(team, r);
                MadeUpRows own;
                built[static_cast<std::size_t>(r)] = buildPatchMatrix(own, 23, 1ull << 30, "made-up", member);
            });
        for (std::thread& t : threads) t.join();
        for (const PatchMatrix& m : built) {
            EXPECT_EQ(m.F.rowStart, one.F.rowStart) << size;
            EXPECT_EQ(m.F.column, one.F.column) << size;
            ASSERT_EQ(m.F.value.size(), one.F.value.size());
            EXPECT_EQ(std::memcmp(m.F.value.data(), one.F.value.data(), one.F.value.size() * sizeof(float)), 0);
            EXPECT_EQ(std::memcmp(m.missed.data(), one.missed.data(), one.missed.size() * sizeof(float)), 0);
            EXPECT_EQ(std::memcmp(&m.weightSum, &one.weightSum, sizeof(double)), 0) << size;
        }
    }
}

TEST(ProcessGroup, GatheredTextsArriveInRankOrder) {
    ThreadTeam team(3);
    std::vector<std::vector<std::string>> got(3);
    std::vector<std::thread> threads;
    const std::vector<std::string> texts = {"NVIDIA CUDA: H200", "", "Portable Computing Language: cpu, 16 cores"};
    for (int r = 0; r < 3; ++r)
        threads.emplace_back([&, r] {
            const ThreadTeam::Member member(team, r);
            got[static_cast<std::size_t>(r)] = gatherTexts(member, texts[static_cast<std::size_t>(r)]);
        });
    for (std::thread& t : threads) t.join();
    for (const auto& g : got) EXPECT_EQ(g, texts);
}

}  // namespace
}  // namespace rad
