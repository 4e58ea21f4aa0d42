#include "apps/stop_signals.h"

#include <csignal>

namespace fluence::app {

namespace {

std::atomic<bool> stopRequested{false};
static_assert(std::atomic<bool>::is_always_lock_free, "set from a signal handler");

struct sigaction previousTerm, previousInt;

extern "C" void requestStop(int) { stopRequested.store(true); }

}  // namespace

StopSignals::StopSignals() {
    struct sigaction action = {};
    action.sa_handler = requestStop;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESETHAND;
    sigaction(SIGTERM, &action, &previousTerm);
    sigaction(SIGINT, &action, &previousInt);
}

StopSignals::~StopSignals() {
    sigaction(SIGTERM, &previousTerm, nullptr);
    sigaction(SIGINT, &previousInt, nullptr);
}

const std::atomic<bool>& StopSignals::flag() { return stopRequested; }

}  // namespace fluence::app
