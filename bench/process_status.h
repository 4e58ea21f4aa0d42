// Shared by the benchmarks: this process's memory figures from /proc/self/status.
#pragma once

#include <cstdlib>
#include <fstream>
#include <string>

namespace fluence::bench {

// A field of /proc/self/status in KiB ("VmHWM", "VmRSS"), or -1 when it cannot be read.
inline long statusKiB(const char* field) {
    std::ifstream status("/proc/self/status");
    std::string line, prefix = std::string(field) + ":";
    while (std::getline(status, line))
        if (line.rfind(prefix, 0) == 0) return std::strtol(line.c_str() + prefix.size(), nullptr, 10);
    return -1;
}

}  // namespace fluence::bench
