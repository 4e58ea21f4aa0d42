// SIGTERM and SIGINT stop a render cleanly, as farm schedulers expect: the first one sets a flag
// the render loop reads between tiles (integrators::RenderSettings::stop), the render ends without
// writing anything to its output path, and `fluence` exits with kExitInterrupted. A second signal
// of the same kind is not caught (SA_RESETHAND): it ends the process at once, for a user who does
// not want to wait for the tiles in flight.
#pragma once

#include <atomic>

namespace fluence::app {

class StopSignals {
public:
    StopSignals();   // installs the handlers
    ~StopSignals();  // restores the previous ones
    StopSignals(const StopSignals&) = delete;
    StopSignals& operator=(const StopSignals&) = delete;

    // Set once SIGTERM or SIGINT has arrived.
    static const std::atomic<bool>& flag();
};

}  // namespace fluence::app
