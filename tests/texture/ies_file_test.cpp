// texture::readIesFile: LM-63 files read back value by value (2002, 1995 with TILT=INCLUDE,
// 1986 without a header), and every refusal naming file:line.
#include <gtest/gtest.h>

#include <fstream>

#include "tests/support/temp_dir.h"
#include "texture/ies_file.h"

namespace fluence::texture {
namespace {

// An LM-63-2002 file with a quadrant-symmetric type C table, its numbers split over lines and
// separated by commas and blanks as real files do.
const char* kQuadrant = R"(IESNA:LM-63-2002
[TEST] hand-written
[MANUFAC] none
TILT=NONE
1 1000 2.0 3 2 1 2 0.1 0.2 0
1.0 1.0 40
0 45 90
0, 90
100 50
10
80 40 0
)";

TEST(IesFile, ReadsTheTableTimesTheCandelaMultiplier) {
    IesTable t = parseIes(kQuadrant, "quad.ies");
    EXPECT_EQ(t.standard, "IESNA:LM-63-2002");
    EXPECT_EQ(t.verticalDegrees, (std::vector<float>{0.0f, 45.0f, 90.0f}));
    EXPECT_EQ(t.horizontalDegrees, (std::vector<float>{0.0f, 90.0f}));
    EXPECT_EQ(t.candela, (std::vector<float>{200.0f, 100.0f, 20.0f, 160.0f, 80.0f, 0.0f}));
    EXPECT_EQ(t.at(1, 1), 80.0f);
}

TEST(IesFile, SkipsIncludedTiltDataAndReadsFilesWithoutAHeader) {
    IesTable tilted = parseIes(
        "IESNA:LM-63-1995\r\nTILT=INCLUDE\r\n1\r\n3\r\n0 45 90\r\n1 0.9 0.8\r\n"
        "1 -1 1 2 1 1 1 0 0 0\r\n1 1 10\r\n0 90\r\n0\r\n7 3\r\n",
        "tilt.ies");
    EXPECT_EQ(tilted.candela, (std::vector<float>{7.0f, 3.0f}));
    IesTable old = parseIes("a 1986 file\nTILT=NONE\n1 -1 1 2 1 1 1 0 0 0\n1 1 10\n0 180\n0\n5 6\n", "old.ies");
    EXPECT_EQ(old.standard, "");
    EXPECT_EQ(old.verticalDegrees, (std::vector<float>{0.0f, 180.0f}));
    EXPECT_EQ(old.candela, (std::vector<float>{5.0f, 6.0f}));
}

TEST(IesFile, ReadsAFileFromDisk) {
    test::TempDir dir;
    std::ofstream(dir.file("lamp.ies")) << kQuadrant;
    EXPECT_EQ(readIesFile(dir.file("lamp.ies")).candela.size(), 6u);
    try {
        readIesFile(dir.file("absent.ies"));
        FAIL() << "no error";
    } catch (const IesFileError& e) {
        EXPECT_EQ(std::string(e.what()), dir.file("absent.ies") + ": cannot be opened");
    }
}

std::string errorOf(const std::string& text) {
    try {
        parseIes(text, "bad.ies");
    } catch (const IesFileError& e) {
        return e.what();
    }
    return "no error";
}

TEST(IesFile, RefusesWhatItCannotReadNamingFileAndLine) {
    const std::string head = "IESNA:LM-63-2002\nTILT=NONE\n";
    EXPECT_EQ(errorOf("IESNA:LM-63-2002\n[TEST] x\n"), "bad.ies:2: no TILT= line: not an IES LM-63 file");
    EXPECT_EQ(errorOf("IESNA:LM-63-2002\nTILT=lamp.tlt\n"),
              "bad.ies:2: TILT=lamp.tlt: tilt data in another file is not supported (TILT=NONE or INCLUDE)");
    EXPECT_EQ(errorOf(head + "1 -1 1 2 1 2 1 0 0 0\n"),
              "bad.ies:3: photometric type B (2) is not supported: only type C (1)");
    EXPECT_EQ(errorOf(head + "1 -1 1 2 1 1 1 0 0 0\n1 1 x10\n"), "bad.ies:4: 'x10' is not a number (the input watts)");
    EXPECT_EQ(errorOf(head + "1 -1 1 2 1 1 1 0 0 0\n1 1 10\n0 0\n"), "bad.ies:5: the vertical angles do not increase");
    EXPECT_EQ(errorOf(head + "1 -1 1 2 1 1 1 0 0 0\n1 1 10\n0 90\n45\n"),
              "bad.ies:6: type C horizontal angles must be 0, 0-90, 0-180, 90-270 or 0-360 degrees");
    EXPECT_EQ(errorOf(head + "1 -1 1 2 1 1 1 0 0 0\n1 1 10\n0 90\n0\n5\n"),
              "bad.ies:7: the file ends before the candela values");
    EXPECT_EQ(errorOf(head + "1 -1 1 2 1 1 1 0 0 0\n1 1 10\n0 90\n0\n5 -1\n"), "bad.ies:7: a negative candela value");
    EXPECT_EQ(errorOf(head + "1 -1 1 2 1 1 1 0 0 0\n1 1 10\n0 90\n0\n5 1\n9\n"),
              "bad.ies:8: numbers follow the candela values");
}

}  // namespace
}  // namespace fluence::texture
