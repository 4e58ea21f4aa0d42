// Seconds since it was made: the render's per-step times (parse, build, write, total).
#pragma once

#include <chrono>

namespace fluence::app {

class Stopwatch {
public:
    double seconds() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }

private:
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace fluence::app
