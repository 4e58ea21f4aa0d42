// `fluence info` and `fluence render` (16 x 16, 1 spp, one thread) on every USD layer of tests/corpus/,
// the public files listed in tests/corpus/README.md, each checked against its row of
// tests/corpus/expected.tsv: both exit codes, the exit code with --allow-missing when the plain render
// refuses a missing asset, and what the run left: a finite image that is lit, dark (geometry in view,
// no light reaches it) or empty (nothing in view), or, for a refusal, whether stderr names
// file:line:column. Rows whose outcome is wrong today say `known-bug: ...`; any change of outcome
// fails, listing each file with its observed row, ready to paste into the manifest.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/cli.h"
#include "tests/support/temp_dir.h"

namespace fluence {
namespace {

namespace fs = std::filesystem;

const fs::path kCorpus = FLUENCE_SOURCE_DIR "/tests/corpus";
constexpr int kShards = 4;  // the layers are split so that ctest -j runs the shards side by side

// One row of expected.tsv: path (relative to tests/corpus), the outcome, and the row's status
// (`ok`, or `known-bug: why` where today's outcome is wrong).
struct Row {
    std::string path;
    std::string outcome;  // info, render, allow-missing, result: tab-separated
    std::string status;
};

std::vector<std::string> splitTabs(const std::string& line) {
    std::vector<std::string> fields;
    std::stringstream in(line);
    for (std::string field; std::getline(in, field, '\t');) fields.push_back(field);
    return fields;
}

std::vector<Row> readManifest() {
    std::ifstream in(kCorpus / "expected.tsv");
    std::vector<Row> rows;
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line[0] == '#') continue;
        std::vector<std::string> f = splitTabs(line);
        if (f.size() != 6) throw std::runtime_error("expected.tsv: not 6 tab-separated fields: " + line);
        rows.push_back({f[0], f[1] + "\t" + f[2] + "\t" + f[3] + "\t" + f[4], f[5]});
    }
    return rows;
}

bool isLayer(const fs::path& p) {
    const std::string ext = p.extension().string();
    return ext == ".usd" || ext == ".usda" || ext == ".usdc" || ext == ".usdz";
}

std::string exitCode(const test::RunResult& r) { return r.exitCode < 0 ? "signal" : std::to_string(r.exitCode); }

// lit: the beauty is above zero in a pixel geometry covers (alpha); dark: geometry covers a pixel
// but the beauty is zero wherever it does; empty: nothing in view (a dome seen behind nothing, the
// default lights' included, does not count); nonfinite: a NaN or infinite value in any channel.
std::string imageClass(const fs::path& exr) {
    if (!fs::exists(exr)) return "no-image";
    test::ExrImage img = test::readExr(exr);
    for (float v : img.pixels)
        if (!std::isfinite(v)) return "nonfinite";
    bool lit = false, covered = false;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            const bool here = img.at(x, y, "A") > 0.0f;
            covered = covered || here;
            lit = lit || (here && (img.at(x, y, "R") > 0.0f || img.at(x, y, "G") > 0.0f || img.at(x, y, "B") > 0.0f));
        }
    return lit ? "lit" : covered ? "dark" : "empty";
}

std::string firstErrorLine(const std::string& err) {
    std::stringstream in(err);
    std::string first;
    for (std::string line; std::getline(in, line);) {
        if (line.find("error") != std::string::npos) return line;
        if (first.empty()) first = line;
    }
    return first;
}

class RealCorpusCli : public ::testing::TestWithParam<int> {
protected:
    test::TempDir tmp_{"fluence_real_corpus"};
    test::RunResult run(const std::string& args) { return test::runFluence(args, tmp_.path()); }

    // The outcome columns of `layer`'s row, and the stderr line that explains it.
    std::pair<std::string, std::string> observe(const fs::path& layer) {
        const std::string quoted = "'" + layer.string() + "'";
        const fs::path exr = tmp_.path() / "out.exr";
        const std::string render = "render " + quoted + " -o '" + exr.string() + "' -r 16 16 --spp 1 -j 1";
        test::RunResult info = run("info " + quoted);
        fs::remove(exr);
        test::RunResult plain = run(render);
        std::string allowMissing = "-";
        test::RunResult last = plain;
        if (plain.exitCode == 4) {
            last = run(render + " --allow-missing");
            allowMissing = exitCode(last);
        }
        static const std::regex location(":[0-9]+:[0-9]+: ");
        std::string result = last.exitCode == 0                      ? imageClass(exr)
                             : std::regex_search(last.err, location) ? "located"
                                                                     : "unlocated";
        return {exitCode(info) + "\t" + exitCode(plain) + "\t" + allowMissing + "\t" + result,
                firstErrorLine(last.exitCode == 0 ? info.err + plain.err : last.err)};
    }
};

TEST(RealCorpusManifest, ListsEveryLayerOfTheCorpusOnce) {
    std::set<std::string> listed, onDisk;
    for (const Row& row : readManifest()) EXPECT_TRUE(listed.insert(row.path).second) << "listed twice: " << row.path;
    for (const auto& entry : fs::recursive_directory_iterator(kCorpus))
        if (entry.is_regular_file() && isLayer(entry.path()))
            onDisk.insert(fs::relative(entry.path(), kCorpus).string());
    for (const std::string& p : onDisk) EXPECT_TRUE(listed.count(p)) << "not in expected.tsv: " << p;
    for (const std::string& p : listed) EXPECT_TRUE(onDisk.count(p)) << "in expected.tsv but not on disk: " << p;
    EXPECT_GE(listed.size(), 300u);
    // An internal error, a crash or a non-finite image is never a correct outcome.
    const std::regex neverRight("(^|\t)(1|signal)(\t|$)|\t(nonfinite|no-image)$");
    for (const Row& row : readManifest()) {
        EXPECT_TRUE(row.status == "ok" || row.status.starts_with("known-bug: "))
            << row.path << ": status " << row.status;
        if (std::regex_search(row.outcome, neverRight)) {
            EXPECT_NE(row.status, "ok") << row.path << ": " << row.outcome;
        }
    }
}

TEST_P(RealCorpusCli, EveryLayerHasItsRecordedOutcome) {
    const std::vector<Row> rows = readManifest();
    std::string mismatches;
    int checked = 0;
    for (std::size_t i = GetParam(); i < rows.size(); i += kShards) {
        const Row& row = rows[i];
        auto [outcome, why] = observe(kCorpus / row.path);
        ++checked;
        if (outcome == row.outcome) continue;
        mismatches += "observed: " + row.path + "\t" + outcome + "\t" + row.status + "\n    expected: " + row.outcome +
                      (row.status == "ok" ? "" : "  (" + row.status + ": fixed? update the row)") +
                      "\n    stderr: " + why + "\n";
    }
    EXPECT_TRUE(mismatches.empty()) << "outcomes that changed (path, info, render, allow-missing, result, status):\n"
                                    << mismatches;
    EXPECT_GT(checked, 0);
}

INSTANTIATE_TEST_SUITE_P(Shard, RealCorpusCli, ::testing::Range(0, kShards));

}  // namespace
}  // namespace fluence
