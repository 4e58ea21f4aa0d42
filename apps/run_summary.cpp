#include "apps/run_summary.h"

#include <sys/resource.h>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>

#include "output/atomic_file.h"
#include "version.h"

namespace fluence::app {

namespace {

std::string quoted(const std::string& text) {
    std::string out = "\"";
    for (unsigned char c : text) {
        if (c == '"' || c == '\\') {
            out += '\\';
            out += char(c);
        } else if (c < 0x20) {
            char escape[8];
            std::snprintf(escape, sizeof escape, "\\u%04x", c);
            out += escape;
        } else {
            out += char(c);
        }
    }
    return out + "\"";
}

std::string number(double v) {
    if (!std::isfinite(v)) return "null";
    char buffer[32];
    auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, v);
    return error == std::errc() ? std::string(buffer, end) : "null";
}

long peakResidentBytes() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_maxrss * 1024L;  // Linux reports kilobytes
}

std::string frameJson(const FrameSummary& f) {
    return "{\"time\": " + number(f.time) + ", \"output\": " + quoted(f.output) + ", \"integrator\": " + quoted(f.integrator) +
           ", \"camera\": " + quoted(f.camera) + ", \"resolution\": [" + std::to_string(f.width) + ", " +
           std::to_string(f.height) + "], \"samplesPerPixel\": " + std::to_string(f.samplesPerPixel) +
           ", \"samples\": " + std::to_string(f.samples) + ", \"rays\": {\"camera\": " + std::to_string(f.cameraRays) +
           ", \"bounce\": " + std::to_string(f.bounceRays) + ", \"shadow\": " + std::to_string(f.shadowRays) +
           "}, \"nonFiniteSamples\": " + std::to_string(f.nonFiniteSamples) + ", \"seconds\": {\"build\": " +
           number(f.buildSeconds) + ", \"render\": " + number(f.renderSeconds) + ", \"write\": " + number(f.writeSeconds) +
           ", \"total\": " + number(f.totalSeconds) + "}}";
}

}  // namespace

std::string summaryJson(const RunSummary& s) {
    std::string json = "{\n  \"fluence\": " + quoted(kFluenceVersion) + ",\n  \"scene\": " + quoted(s.scene) +
                       ",\n  \"exitCode\": " + std::to_string(s.exitCode) + ",\n  \"seed\": " + std::to_string(s.seed) +
                       ",\n  \"threads\": " + std::to_string(s.threads) + ",\n  \"parseSeconds\": " + number(s.parseSeconds) +
                       ",\n  \"peakMemoryBytes\": " + std::to_string(peakResidentBytes()) + ",\n  \"warnings\": [";
    for (std::size_t i = 0; i < s.warnings.size(); ++i)
        json += std::string(i ? "," : "") + "\n    {\"where\": " + quoted(s.warnings[i].first) + ", \"message\": " +
                quoted(s.warnings[i].second) + "}";
    json += std::string(s.warnings.empty() ? "" : "\n  ") + "],\n  \"frames\": [";
    for (std::size_t i = 0; i < s.frames.size(); ++i) json += std::string(i ? "," : "") + "\n    " + frameJson(s.frames[i]);
    return json + std::string(s.frames.empty() ? "" : "\n  ") + "]\n}\n";
}

void writeSummary(const std::string& path, const RunSummary& summary) {
    const std::string json = summaryJson(summary);
    output::writeAtomically(path, [&](const std::string& temp) {
        std::ofstream out(temp, std::ios::binary);
        out << json;
        if (!out.flush()) throw output::OutputError("cannot write " + path);
    });
}

}  // namespace fluence::app
