#include "apps/progress_reporter.h"

#include <unistd.h>

#include <cstdio>

namespace fluence::app {

namespace {
constexpr auto kTerminalInterval = std::chrono::milliseconds(200);
constexpr auto kPipeInterval = std::chrono::milliseconds(500);
constexpr double kPipeRepeatSeconds = 5.0;
constexpr int kBarWidth = 40;
}  // namespace

ProgressReporter::ProgressReporter(const integrators::RenderProgress& progress, ProgressStyle style)
    : progress_(progress),
      style_(style),
      terminal_(style == ProgressStyle::Auto && isatty(STDERR_FILENO) != 0),
      start_(std::chrono::steady_clock::now()),
      thread_([this] { run(); }) {}

ProgressReporter::~ProgressReporter() { finish(); }

void ProgressReporter::finish() {
    {
        std::lock_guard lock(mutex_);
        if (stop_) return;
        stop_ = true;
    }
    wake_.notify_all();
    thread_.join();
    report(true);
}

void ProgressReporter::run() {
    std::unique_lock lock(mutex_);
    while (!stop_) {
        wake_.wait_for(lock, terminal_ ? kTerminalInterval : kPipeInterval);
        if (!stop_) report(false);
    }
}

void ProgressReporter::report(bool final) {
    if (style_ == ProgressStyle::None) return;
    std::uint64_t planned = progress_.pixelSamplesPlanned.load(std::memory_order_relaxed);
    std::uint64_t done = progress_.pixelSamplesDone.load(std::memory_order_relaxed);
    double fraction = planned > 0 ? std::min(1.0, double(done) / double(planned)) : 0.0;
    if (final) fraction = 1.0;
    int percent = static_cast<int>(fraction * 100.0);
    double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();

    if (terminal_) {
        int filled = static_cast<int>(fraction * kBarWidth);
        char bar[kBarWidth + 1];
        for (int i = 0; i < kBarWidth; ++i) bar[i] = i < filled ? '=' : (i == filled ? '>' : ' ');
        bar[kBarWidth] = '\0';
        double left = fraction > 0.0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
        std::fprintf(stderr, "\r[%s] %3d%%  %6.1fs elapsed  %6.1fs left ", bar, percent, elapsed, left);
        if (final) std::fputc('\n', stderr);
        std::fflush(stderr);
        return;
    }
    if (percent != lastPercent_ || elapsed - lastPrint_ >= kPipeRepeatSeconds) {
        std::printf("ALF_PROGRESS %d%%\n", percent);
        std::fflush(stdout);
        lastPercent_ = percent;
        lastPrint_ = elapsed;
    }
}

}  // namespace fluence::app
