#include "apps/snapshot_signal.h"

#include <atomic>
#include <csignal>

namespace fluence::app {

namespace {

std::atomic<bool> snapshotRequested{false};
static_assert(std::atomic<bool>::is_always_lock_free, "set from a signal handler");

struct sigaction previousUsr1;

extern "C" void requestSnapshot(int) { snapshotRequested.store(true); }

}  // namespace

SnapshotSignal::SnapshotSignal() {
    struct sigaction action = {};
    action.sa_handler = requestSnapshot;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;
    sigaction(SIGUSR1, &action, &previousUsr1);
}

SnapshotSignal::~SnapshotSignal() { sigaction(SIGUSR1, &previousUsr1, nullptr); }

bool SnapshotSignal::take() { return snapshotRequested.exchange(false); }

}  // namespace fluence::app
