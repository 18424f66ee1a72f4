#include "runtime/app/ShutdownSignals.hpp"

#include <atomic>
#include <csignal>

namespace arcomp {

namespace {

// Lock-free atomics are async-signal-safe; nothing else is touched in a handler.
std::atomic<bool> stopFlag{false};
std::atomic<bool> reloadFlag{false};
static_assert(std::atomic<bool>::is_always_lock_free);

extern "C" void onStopSignal(int) { stopFlag.store(true); }
extern "C" void onReloadSignal(int) { reloadFlag.store(true); }

}  // namespace

void installShutdownSignals() {
    struct sigaction stop {};
    stop.sa_handler = onStopSignal;
    sigemptyset(&stop.sa_mask);
    sigaction(SIGTERM, &stop, nullptr);
    sigaction(SIGINT, &stop, nullptr);
    struct sigaction reload {};
    reload.sa_handler = onReloadSignal;
    sigemptyset(&reload.sa_mask);
    reload.sa_flags = SA_RESTART;
    sigaction(SIGHUP, &reload, nullptr);
}

bool stopRequested() { return stopFlag.load(); }
bool takeReloadRequest() { return reloadFlag.exchange(false); }
void requestStop() { stopFlag.store(true); }
void requestReload() { reloadFlag.store(true); }

}  // namespace arcomp
