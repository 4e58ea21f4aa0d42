// How fast binary USD loads (issue #11): every crate file of the Open Chess Set read by the crate
// reader (MB/s, best of 5 reads of each file), and the composed stage of chess_set.usda (crate
// geometry, payloads, variants, MaterialX looks) opened whole. Time to first pixel is measured
// with `fluence render --summary` (bench/results/2026-11-27-crate-loading.md).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "scene/crate_reader.h"
#include "scene/stage.h"

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

namespace {

double secondsSince(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

template <typename F>
double bestOf(int runs, F&& f) {
    double best = 1e30;
    for (int i = 0; i < runs; ++i) {
        const auto t = Clock::now();
        f();
        best = std::min(best, secondsSince(t));
    }
    return best;
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
    std::printf("%-28s %10s %10s %10s\n", "crate file", "MB", "ms", "MB/s");
    double totalBytes = 0.0, totalSeconds = 0.0;
    for (const fs::path& file : crates) {
        const double bytes = double(fs::file_size(file));
        const double seconds = bestOf(5, [&] { fluence::usd::readCrateFile(file.string()); });
        totalBytes += bytes;
        totalSeconds += seconds;
        std::printf("%-28s %10.2f %10.2f %10.1f\n", file.filename().c_str(), bytes / 1e6, seconds * 1e3, bytes / 1e6 / seconds);
    }
    std::printf("%-28s %10.2f %10.2f %10.1f\n", "all", totalBytes / 1e6, totalSeconds * 1e3, totalBytes / 1e6 / totalSeconds);
    const double open = bestOf(3, [&] { fluence::usd::Stage::open((chess / "chess_set.usda").string()); });
    std::printf("\nStage::open(chess_set.usda), composed: %.3f s (best of 3)\n", open);
}
