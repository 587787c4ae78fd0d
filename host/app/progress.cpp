#include "app/progress.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <unistd.h>

namespace rad {

ProgressDisplay::ProgressDisplay(double tolerance) : tolerance_(tolerance), terminal_(::isatty(2) != 0) {}

void ProgressDisplay::update(const SolveProgress& p) {
    const double interval = terminal_ ? 0.1 : 5.0;
    if (p.seconds - lastPrint_ < interval) return;
    lastPrint_ = p.seconds;
    // Unshot power falls about exponentially: progress is measured in its logarithm.
    const double f = std::max(p.unshotFraction, 1e-300);
    const double done = tolerance_ < 1.0 ? std::clamp(std::log(f) / std::log(tolerance_), 0.0, 1.0) : 1.0;
    const double rate = p.seconds > 0 ? p.rays / p.seconds : 0.0;
    char left[32] = "?";
    if (done > 0.02 && p.seconds > 0.5) std::snprintf(left, sizeof left, "%.0f s", p.seconds * (1.0 - done) / done);
    if (terminal_) {
        char bar[31];
        const int filled = static_cast<int>(done * 30.0);
        for (int i = 0; i < 30; ++i) bar[i] = i < filled ? '=' : (i == filled ? '>' : ' ');
        bar[30] = '\0';
        std::fprintf(stderr, "\r[%s] %llu shots, unshot %.2e, %.2f Mrays/s, left %s   ", bar,
                     static_cast<unsigned long long>(p.shots), p.unshotFraction, rate * 1e-6, left);
        drawn_ = true;
    } else {
        std::fprintf(stderr, "solve: %.0f s, %llu shots, unshot %.2e, %.2f Mrays/s, left %s\n", p.seconds,
                     static_cast<unsigned long long>(p.shots), p.unshotFraction, rate * 1e-6, left);
    }
    std::fflush(stderr);
}

void ProgressDisplay::finish() {
    if (drawn_) std::fprintf(stderr, "\n");
    drawn_ = false;
}

}  // namespace rad
