// Reports render progress while the render runs, from a thread of its own.
//
// On a terminal (stderr is a TTY) it redraws a progress bar with elapsed time and an estimate of
// the time left. Otherwise it prints `ALF_PROGRESS n%` lines on stdout — the format farm
// schedulers (Tractor, Deadline, OpenCue plugins) parse for husk and PRMan — whenever the whole
// percentage changes, and at least every 5 seconds. `-V a` (ProgressStyle::Alfred) asks for those
// lines on a terminal too; `-V 0` (ProgressStyle::None) for no progress at all.
#pragma once

#include <atomic>
#include <condition_variable>
#include <mutex>
#include <thread>

#include "integrators/renderer.h"

namespace fluence::app {

// How progress is shown (husk's -V: a verbosity digit, 'a' for Alfred-style lines).
enum class ProgressStyle {
    Auto,    // a bar on a terminal, ALF_PROGRESS lines otherwise
    Alfred,  // ALF_PROGRESS lines on stdout
    None,    // nothing
};

class ProgressReporter {
public:
    ProgressReporter(const integrators::RenderProgress& progress, ProgressStyle style);
    ~ProgressReporter();  // stops and prints the final state
    void finish();

private:
    void run();
    void report(bool final);

    const integrators::RenderProgress& progress_;
    ProgressStyle style_;
    bool terminal_;
    int lastPercent_ = -1;
    double lastPrint_ = -1e9;
    std::chrono::steady_clock::time_point start_;
    std::mutex mutex_;
    std::condition_variable wake_;
    bool stop_ = false;
    std::thread thread_;
};

}  // namespace fluence::app
