// `fluence render --summary run.json`: what a render did, for farm tools and pipelines to read
// instead of parsing the log. Written atomically when the command ends, whether it succeeded or
// not (then with the exit code and the frames that were done):
//   { "fluence": version, "scene": path, "exitCode": n, "seed": s, "threads": n,
//     "peakMemoryBytes": n,                    (the process's peak resident set)
//     "warnings": [{"where": ..., "message": ...}, ...],
//     "frames": [{ "time": t (null: default values), "output": path, "integrator": name,
//                  "camera": path, "resolution": [w, h], "samplesPerPixel": n, "samples": n,
//                  "rays": {"camera": n, "bounce": n, "shadow": n}, "nonFiniteSamples": n,
//                  "seconds": {"build": s, "render": s, "write": s, "total": s} }, ...],
//     "parseSeconds": s }
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace fluence::app {

struct FrameSummary {
    double time = 0.0;  // NaN: USD's default time
    std::string output, integrator, camera;
    int width = 0, height = 0, samplesPerPixel = 0;
    std::uint64_t samples = 0, cameraRays = 0, bounceRays = 0, shadowRays = 0, nonFiniteSamples = 0;
    double buildSeconds = 0.0, renderSeconds = 0.0, writeSeconds = 0.0, totalSeconds = 0.0;
    double renderCpuSeconds = 0.0;  // the render's CPU time, every thread (integrators::RenderStats::cpuSeconds)
};

struct RunSummary {
    std::string scene;
    int exitCode = 0;
    std::uint64_t seed = 0;
    int threads = 0;
    double parseSeconds = 0.0;
    std::vector<std::pair<std::string, std::string>> warnings;  // where, message
    std::vector<FrameSummary> frames;
};

// The summary as JSON (peak memory read from the process when called).
std::string summaryJson(const RunSummary& summary);

// Writes summaryJson() to `path` atomically. Throws output::OutputError when it cannot.
void writeSummary(const std::string& path, const RunSummary& summary);

}  // namespace fluence::app
