#include "app/interrupt.h"

#include <csignal>

namespace rad {
namespace {

volatile std::sig_atomic_t requested = 0;

extern "C" void onSignal(int signal) {
    if (requested) {
        std::signal(signal, SIG_DFL);
        std::raise(signal);
        return;
    }
    requested = 1;
}

}  // namespace

void installInterruptHandlers() {
    std::signal(SIGINT, onSignal);
    std::signal(SIGTERM, onSignal);
}

bool interruptRequested() { return requested != 0; }

void clearInterruptRequest() { requested = 0; }

}  // namespace rad
