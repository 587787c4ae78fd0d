#include "parallel/process_group.h"

#include <algorithm>
#include <cstring>
#include <numeric>

#include "util/error.h"

namespace rad {
namespace {

class OneProcess : public ProcessGroup {
public:
    int rank() const override { return 0; }
    int size() const override { return 1; }
    void sum(std::vector<std::uint64_t>&) const override {}
    std::vector<std::uint64_t> allGather(const std::vector<std::uint64_t>& mine) const override { return mine; }
};

}  // namespace

const ProcessGroup& oneProcess() {
    static const OneProcess group;
    return group;
}

bool anyProcess(const ProcessGroup& group, bool mine) {
    if (group.size() == 1) return mine;
    std::vector<std::uint64_t> count{mine ? 1u : 0u};
    group.sum(count);
    return count[0] > 0;
}

std::vector<std::string> gatherTexts(const ProcessGroup& group, const std::string& mine) {
    // Each text as its length, then its bytes packed eight to a word.
    std::vector<std::uint64_t> packed(1 + (mine.size() + 7) / 8, 0);
    packed[0] = mine.size();
    if (!mine.empty()) std::memcpy(packed.data() + 1, mine.data(), mine.size());
    const std::vector<std::uint64_t> all = group.allGather(packed);
    std::vector<std::string> texts;
    for (std::size_t at = 0; at < all.size();) {
        const std::size_t length = static_cast<std::size_t>(all[at]);
        const std::size_t words = (length + 7) / 8;
        if (at + 1 + words > all.size()) throw RuntimeFailure("the processes' texts arrived damaged");
        std::string text(length, '\0');
        if (length > 0) std::memcpy(&text[0], all.data() + at + 1, length);
        texts.push_back(std::move(text));
        at += 1 + words;
    }
    return texts;
}

std::vector<std::uint32_t> divideByCost(const std::vector<std::uint64_t>& costs, int processes) {
    std::vector<std::uint32_t> owner(costs.size(), 0);
    if (processes <= 1) return owner;
    std::vector<std::size_t> order(costs.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return costs[a] > costs[b]; });
    std::vector<std::uint64_t> load(static_cast<std::size_t>(processes), 0);
    for (std::size_t task : order) {
        const std::size_t least = static_cast<std::size_t>(std::min_element(load.begin(), load.end()) - load.begin());
        owner[task] = static_cast<std::uint32_t>(least);
        load[least] += costs[task];
    }
    return owner;
}

}  // namespace rad
