#include "apps/run_summary.h"

#include <sys/resource.h>

#include <fstream>

#include "apps/json.h"
#include "output/atomic_file.h"
#include "version.h"

namespace fluence::app {

namespace {

long peakResidentBytes() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_maxrss * 1024L;  // Linux reports kilobytes
}

std::string frameJson(const FrameSummary& f) {
    return "{\"time\": " + jsonNumber(f.time) + ", \"output\": " + jsonQuoted(f.output) +
           ", \"integrator\": " + jsonQuoted(f.integrator) + ", \"camera\": " + jsonQuoted(f.camera) +
           ", \"resolution\": [" + std::to_string(f.width) + ", " + std::to_string(f.height) +
           "], \"samplesPerPixel\": " + std::to_string(f.samplesPerPixel) +
           ", \"samples\": " + std::to_string(f.samples) + ", \"rays\": {\"camera\": " + std::to_string(f.cameraRays) +
           ", \"bounce\": " + std::to_string(f.bounceRays) + ", \"shadow\": " + std::to_string(f.shadowRays) +
           "}, \"nonFiniteSamples\": " + std::to_string(f.nonFiniteSamples) +
           ", \"seconds\": {\"build\": " + jsonNumber(f.buildSeconds) + ", \"render\": " + jsonNumber(f.renderSeconds) +
           ", \"renderCpu\": " + jsonNumber(f.renderCpuSeconds) + ", \"write\": " + jsonNumber(f.writeSeconds) +
           ", \"total\": " + jsonNumber(f.totalSeconds) + "}}";
}

}  // namespace

std::string summaryJson(const RunSummary& s) {
    std::string json = "{\n  \"fluence\": " + jsonQuoted(kFluenceVersion) + ",\n  \"scene\": " + jsonQuoted(s.scene) +
                       ",\n  \"exitCode\": " + std::to_string(s.exitCode) + ",\n  \"seed\": " + std::to_string(s.seed) +
                       ",\n  \"threads\": " + std::to_string(s.threads) +
                       ",\n  \"parseSeconds\": " + jsonNumber(s.parseSeconds) +
                       ",\n  \"peakMemoryBytes\": " + std::to_string(peakResidentBytes()) + ",\n  \"warnings\": [";
    for (std::size_t i = 0; i < s.warnings.size(); ++i)
        json += std::string(i ? "," : "") + "\n    {\"where\": " + jsonQuoted(s.warnings[i].first) +
                ", \"message\": " + jsonQuoted(s.warnings[i].second) + "}";
    json += std::string(s.warnings.empty() ? "" : "\n  ") + "],\n  \"frames\": [";
    for (std::size_t i = 0; i < s.frames.size(); ++i)
        json += std::string(i ? "," : "") + "\n    " + frameJson(s.frames[i]);
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
