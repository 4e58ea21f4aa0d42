// How fast binary USD loads (issue #11): every crate file of the Open Chess Set read by the crate
// reader, alone and then with every number of its values read (the reader decodes large arrays on
// first use), in CPU milliseconds and MB/s (best of 5 each); and the composed stage of
// chess_set.usda (crate geometry, payloads, variants, MaterialX looks) opened whole. Time to first pixel is measured
// with `fluence render --summary` (bench/results/2026-11-27-crate-loading.md). The stage is opened
// first, so the peak resident set printed after it (VmHWM) is that of opening the stage alone.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "bench/process_status.h"
#include "scene/crate_reader.h"
#include "scene/stage.h"

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

namespace {

// This process's CPU time (every thread's), in seconds.
double cpuSeconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) + double(t.tv_nsec) * 1e-9;
}

// The best of `runs` timings of `f`: wall-clock seconds, and CPU seconds (what a loaded, shared
// machine does not inflate by running other work in between).
struct Timing {
    double wall = 1e30, cpu = 1e30;
};
template <typename F>
Timing bestOf(int runs, F&& f) {
    Timing best;
    for (int i = 0; i < runs; ++i) {
        const auto t = Clock::now();
        const double c = cpuSeconds();
        f();
        best.cpu = std::min(best.cpu, cpuSeconds() - c);
        best.wall = std::min(best.wall, std::chrono::duration<double>(Clock::now() - t).count());
    }
    return best;
}

// Reads every number of every attribute value under `prim`, so that arrays decoded on first use are
// decoded; returns their count (so the reads cannot be optimised away).
std::size_t touchNumbers(const fluence::usd::PrimSpec& prim) {
    std::size_t count = 0;
    auto touch = [&](const fluence::usd::Value& value) {
        for (double x : value.numbers) count += x == x;
    };
    auto touchBody = [&](const auto& body) {
        for (const auto& attribute : body.attributes) {
            touch(attribute.defaultValue);
            for (const auto& sample : attribute.timeSamples) touch(sample.second);
        }
        for (const auto& child : body.children) count += touchNumbers(*child);
    };
    touchBody(prim);
    for (const auto& set : prim.variantSets)
        for (const auto& variant : set.variants) touchBody(variant);
    return count;
}

}  // namespace

int main() {
    const fs::path chess = fs::path(FLUENCE_SOURCE_DIR) / "../shared/usd_corpus/usd-wg-assets/full_assets/OpenChessSet";
    if (!fs::exists(chess)) {
        std::printf("the Open Chess Set is not at %s\n", chess.string().c_str());
        return 1;
    }
    std::vector<fs::path> crates;
    for (const auto& entry : fs::recursive_directory_iterator(chess))
        if (entry.is_regular_file()) {
            std::FILE* f = std::fopen(entry.path().c_str(), "rb");
            char magic[8] = {};
            const std::size_t n = f ? std::fread(magic, 1, 8, f) : 0;
            if (f) std::fclose(f);
            if (fluence::usd::isCrateHeader(std::string_view(magic, n))) crates.push_back(entry.path());
        }
    std::sort(crates.begin(), crates.end());
    const Timing open = bestOf(3, [&] { fluence::usd::Stage::open((chess / "chess_set.usda").string()); });
    std::printf("Stage::open(chess_set.usda), composed: %.3f s wall, %.3f s CPU (best of 3), peak RSS %.1f MB\n\n",
                open.wall, open.cpu, fluence::bench::statusKiB("VmHWM") / 1024.0);
    // "read": readCrateFile alone; "+ numbers": then every number of every attribute value read.
    // Milliseconds of CPU time, best of 5; MB/s from them.
    std::printf("%-28s %8s %10s %10s %14s %10s\n", "crate file", "MB", "read ms", "MB/s", "+ numbers ms", "MB/s");
    double totalBytes = 0.0, totalRead = 0.0, totalTouched = 0.0;
    std::size_t numbers = 0;
    for (const fs::path& file : crates) {
        const double bytes = double(fs::file_size(file));
        const double read = bestOf(5, [&] { fluence::usd::readCrateFile(file.string()); }).cpu;
        const double touched = bestOf(5, [&] {
                                   const std::unique_ptr<fluence::usd::Layer> layer =
                                       fluence::usd::readCrateFile(file.string());
                                   for (const auto& prim : layer->rootPrims) numbers += touchNumbers(*prim);
                               }).cpu;
        totalBytes += bytes;
        totalRead += read;
        totalTouched += touched;
        std::printf("%-28s %8.2f %10.2f %10.1f %14.2f %10.1f\n", file.filename().c_str(), bytes / 1e6, read * 1e3,
                    bytes / 1e6 / read, touched * 1e3, bytes / 1e6 / touched);
    }
    std::printf("%-28s %8.2f %10.2f %10.1f %14.2f %10.1f\n", "all", totalBytes / 1e6, totalRead * 1e3,
                totalBytes / 1e6 / totalRead, totalTouched * 1e3, totalBytes / 1e6 / totalTouched);
    std::printf("(%zu numbers read in each pass over the files)\n", numbers / 5);
}
