// SIGUSR1 asks a running render for a snapshot of its image so far (`fluence render`, as RenderMan
// and Arnold kick renders do on a signal): the handler only sets a flag (async-signal-safe), and
// the render writes the snapshot at its next pass boundary (apps/pass_outputs.h). Signals that
// arrive before then make one snapshot. Installed for the whole of `fluence render`, so a signal
// sent early never takes SIGUSR1's default action (ending the process).
#pragma once

namespace fluence::app {

class SnapshotSignal {
public:
    SnapshotSignal();   // installs the handler
    ~SnapshotSignal();  // restores the previous one
    SnapshotSignal(const SnapshotSignal&) = delete;
    SnapshotSignal& operator=(const SnapshotSignal&) = delete;

    // Whether SIGUSR1 has arrived since the last call (clears the request).
    static bool take();
};

}  // namespace fluence::app
