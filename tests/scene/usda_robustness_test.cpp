// The USDA reader never crashes, hangs or throws anything but ParseError on damaged input:
// every prefix of a valid file, and random byte mutations of it (fixed seed).
#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include "scene/usda_parser.h"

namespace fluence::usd {
namespace {

std::string readSample() {
    std::ifstream file(FLUENCE_SOURCE_DIR "/tests/scene/data/kitchen_sink.usda", std::ios::binary);
    std::ostringstream text;
    text << file.rdbuf();
    return text.str();
}

// True when the text parses; false when it throws ParseError. Any other exception fails the test.
bool parsesOrFailsCleanly(const std::string& text, const std::string& what) {
    try {
        parseUsdaString(text, "mutated.usda");
        return true;
    } catch (const ParseError& error) {
        std::string prefix = "mutated.usda:";
        EXPECT_EQ(std::string(error.what()).substr(0, prefix.size()), prefix) << what;
        EXPECT_GE(error.location().line, 1) << what;
        EXPECT_GE(error.location().column, 1) << what;
        return false;
    } catch (const std::exception& error) {
        ADD_FAILURE() << what << ": unexpected exception: " << error.what();
        return false;
    }
}

TEST(UsdaRobustness, TheSampleParses) {
    std::string sample = readSample();
    ASSERT_GT(sample.size(), 1000u);
    auto layer = parseUsdaString(sample, "kitchen_sink.usda");
    EXPECT_NE(layer->primAtPath("/Extras"), nullptr);
}

TEST(UsdaRobustness, EveryPrefixParsesOrFailsCleanly) {
    std::string sample = readSample();
    int parsed = 0;
    for (std::size_t length = 0; length <= sample.size(); ++length) {
        if (parsesOrFailsCleanly(sample.substr(0, length), "prefix of " + std::to_string(length))) {
            ++parsed;
        }
    }
    EXPECT_GT(parsed, 0);  // at least the whole file (and prefixes ending between prims)
}

TEST(UsdaRobustness, RandomMutationsParseOrFailCleanly) {
    std::string sample = readSample();
    std::mt19937 random(20240611u);
    auto below = [&](std::size_t n) { return static_cast<std::size_t>(random() % n); };
    const std::string interesting = std::string("\"'@<>()[]{}=,:;.#/*\\-+0123456789eE\n\t ") + '\0' + '\xff';
    int failures = 0;
    const int kMutants = 600;
    for (int mutant = 0; mutant < kMutants; ++mutant) {
        std::string text = sample;
        int edits = 1 + static_cast<int>(below(4));
        for (int edit = 0; edit < edits && !text.empty(); ++edit) {
            std::size_t at = below(text.size());
            switch (below(5)) {
                case 0: text[at] = static_cast<char>(random() & 0xff); break;
                case 1: text.erase(at, 1 + below(8)); break;
                case 2: text.insert(at, 1, interesting[below(interesting.size())]); break;
                case 3: text.insert(at, text.substr(below(text.size()), below(64))); break;
                default: text[at] = interesting[below(interesting.size())]; break;
            }
        }
        if (!parsesOrFailsCleanly(text, "mutant " + std::to_string(mutant))) ++failures;
    }
    EXPECT_GT(failures, kMutants / 2);  // most mutations break the syntax
}

TEST(UsdaRobustness, RandomBytesFailCleanly) {
    std::mt19937 random(7u);
    for (int i = 0; i < 200; ++i) {
        std::string text = i % 2 ? "#usda 1.0\n" : "";
        std::size_t length = random() % 200;
        for (std::size_t j = 0; j < length; ++j) text += static_cast<char>(random() & 0xff);
        parsesOrFailsCleanly(text, "random bytes " + std::to_string(i));
    }
}

}  // namespace
}  // namespace fluence::usd
