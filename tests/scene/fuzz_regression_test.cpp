// Inputs the fuzzer (fuzz/, scripts/fuzz_smoke.sh) once crashed the USDA reader on, kept in
// tests/scene/fuzz_regressions/: every one must now parse, or fail with usd::ParseError, and
// nothing else. Each file runs in a forked child (a gtest death-test assertion), so a file that
// still crashes, aborts, throws another exception or hangs fails this test with its name and the
// child's output, and the remaining files are still checked. Files are listed at run time: a new
// file needs no rebuild. When parsing succeeds, the layer goes through usd::Stage as in the
// fuzzer: traversal and every attribute resolved at the default time and at its sample times.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "scene/stage.h"
#include "scene/usda_parser.h"

namespace fluence::usd {
namespace {

namespace fs = std::filesystem;

const fs::path kRegressions = FLUENCE_SOURCE_DIR "/tests/scene/fuzz_regressions";

// Exit codes of the child, besides 0 (parsed, or ParseError).
constexpr int kOtherException = 3;
constexpr int kUnknownException = 4;
constexpr unsigned kSecondsPerFile = 60;  // a hang is a finding too (SIGALRM ends the child)

std::vector<fs::path> regressionInputs() {
    std::vector<fs::path> files;
    if (!fs::is_directory(kRegressions)) return files;
    for (const auto& entry : fs::directory_iterator(kRegressions)) {
        if (!entry.is_regular_file()) continue;
        if (entry.path().filename().string().rfind("README", 0) == 0) continue;
        files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());
    return files;
}

void resolveEverything(const std::vector<std::unique_ptr<PrimSpec>>& prims) {
    for (const auto& prim : prims) {
        auto resolveAll = [](const std::vector<AttributeSpec>& attributes) {
            for (const AttributeSpec& attribute : attributes) {
                (void)Stage::resolve(attribute, kDefaultTime);
                for (const auto& [time, value] : attribute.timeSamples) {
                    (void)Stage::resolve(attribute, time);
                    (void)Stage::resolve(attribute, time + 0.5);
                    (void)value.toString();
                }
                if (attribute.hasDefault) (void)attribute.defaultValue.toString();
            }
        };
        resolveAll(prim->attributes);
        for (const VariantSetSpec& set : prim->variantSets) {
            for (const VariantSpec& variant : set.variants) {
                resolveAll(variant.attributes);
                resolveEverything(variant.children);
            }
        }
        for (const MetadataEntry& entry : prim->metadata) (void)entry.value.toString();
        resolveEverything(prim->children);
    }
}

// Runs in the child: exits 0 when the text parses (and reads back) or throws ParseError.
[[noreturn]] void parseOrFailCleanly(const fs::path& path) {
    alarm(kSecondsPerFile);
    std::ifstream file(path, std::ios::binary);
    std::ostringstream text;
    text << file.rdbuf();
    try {
        std::unique_ptr<Layer> layer = parseUsdaString(text.str(), path.filename().string());
        resolveEverything(layer->rootPrims);
        for (const MetadataEntry& entry : layer->metadata) (void)entry.value.toString();
        Stage stage(std::move(layer));
        (void)stage.defaultPrim();
        (void)stage.upAxis();
        (void)stage.metersPerUnit();
        (void)stage.startTimeCode();
        stage.traverse([](const PrimSpec&) { return true; });
    } catch (const ParseError&) {
        std::exit(0);
    } catch (const std::exception& error) {
        std::fprintf(stderr, "unexpected exception: %s\n", error.what());
        std::exit(kOtherException);
    } catch (...) {
        std::fprintf(stderr, "unexpected exception of unknown type\n");
        std::exit(kUnknownException);
    }
    std::exit(0);
}

TEST(FuzzRegressions, TheFolderIsThere) { EXPECT_TRUE(fs::exists(kRegressions / "README.md")) << kRegressions; }

TEST(FuzzRegressions, EveryInputParsesOrFailsWithParseError) {
    std::vector<fs::path> inputs = regressionInputs();
    for (const fs::path& input : inputs) {
        EXPECT_EXIT(parseOrFailCleanly(input), testing::ExitedWithCode(0), "")
            << input.filename() << " (tests/scene/fuzz_regressions) did not parse or fail with "
            << "usd::ParseError; reproduce with build/fuzz/usda_fuzzer " << input;
    }
    std::cout << "[ fuzz     ] " << inputs.size() << " regression inputs checked\n";
}

}  // namespace
}  // namespace fluence::usd
