// apps/review_files.h: what `fluence review` serves from the paths it is given.
#include "apps/review_files.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "tests/support/temp_dir.h"

namespace fluence::app {
namespace {

namespace fs = std::filesystem;

void touch(const fs::path& path) {
    fs::create_directories(path.parent_path());
    std::ofstream(path) << "x";
}

std::vector<std::string> names(const std::vector<ReviewFile>& files) {
    std::vector<std::string> out;
    for (const ReviewFile& f : files) out.push_back(f.name);
    return out;
}

TEST(ReviewFiles, AFolderListsItsExrFilesAndGroupsNumberedOnesIntoASequence) {
    test::TempDir dir;
    touch(dir.path() / "out/beauty.0002.exr");
    touch(dir.path() / "out/beauty.0001.exr");
    touch(dir.path() / "out/ref.exr");
    touch(dir.path() / "out/notes.txt");
    touch(dir.path() / "out/aovs/albedo.exr");
    const auto files = expandReviewPaths({(dir.path() / "out").string()});
    EXPECT_EQ(names(files), (std::vector<std::string>{"out/aovs/albedo.exr", "out/beauty.0001.exr",
                                                      "out/beauty.0002.exr", "out/ref.exr"}));
    EXPECT_EQ(files[1].sequence, "out/beauty.####.exr");
    EXPECT_EQ(files[1].frame, 1);
    EXPECT_EQ(files[2].frame, 2);
    EXPECT_EQ(files[3].sequence, "");
}

TEST(ReviewFiles, FrameSequencePatternsExpandToTheFramesPresentInOrder) {
    test::TempDir dir;
    for (const char* name : {"r.0010.exr", "r.0009.exr", "r.10.exr", "r.0011.exr.bak"}) touch(dir.path() / name);
    for (const std::string pattern : {"r.$F4.exr", "r.####.exr"}) {
        const auto files = expandReviewPaths({(dir.path() / pattern).string()});
        ASSERT_EQ(files.size(), 2u) << pattern;
        EXPECT_EQ(files[0].frame, 9);
        EXPECT_EQ(files[1].frame, 10);
        EXPECT_EQ(fs::path(files[1].path).filename(), "r.0010.exr");
        EXPECT_EQ(fs::path(files[0].sequence).filename(), "r.####.exr");
    }
    EXPECT_THROW(expandReviewPaths({(dir.path() / "s.$F4.exr").string()}), ReviewInputError);
}

TEST(ReviewFiles, MissingPathsAndEmptyFoldersAreErrorsNamingThePath) {
    test::TempDir dir;
    fs::create_directories(dir.path() / "empty");
    try {
        expandReviewPaths({dir.file("nothing.exr")});
        FAIL() << "no error";
    } catch (const ReviewInputError& e) {
        EXPECT_NE(std::string(e.what()).find("nothing.exr: no such file or folder"), std::string::npos) << e.what();
    }
    EXPECT_THROW(expandReviewPaths({dir.file("empty")}), ReviewInputError);
}

TEST(ReviewFiles, ASymlinkLeavingTheFolderIsNotServed) {
    test::TempDir dir;
    touch(dir.path() / "secret/private.exr");
    touch(dir.path() / "out/a.exr");
    fs::create_symlink(dir.path() / "secret/private.exr", dir.path() / "out/link.exr");
    fs::create_directory_symlink(dir.path() / "secret", dir.path() / "out/linked_folder");
    touch(dir.path() / "out/inside_target.exr");
    fs::create_symlink(dir.path() / "out/inside_target.exr", dir.path() / "out/inside_link.exr");
    const auto files = expandReviewPaths({dir.file("out")});
    EXPECT_EQ(names(files), (std::vector<std::string>{"out/a.exr", "out/inside_link.exr", "out/inside_target.exr"}));
}

TEST(ReviewFiles, UnsafeNamesAreRefusedAndOnlyListedNamesAreFound) {
    test::TempDir dir;
    touch(dir.path() / "out/a.exr");
    const auto files = expandReviewPaths({dir.file("out")});
    EXPECT_TRUE(findReviewFile(files, "out/a.exr"));
    EXPECT_FALSE(findReviewFile(files, "out/b.exr"));
    for (const std::string name :
         {"../out/a.exr", "out/../out/a.exr", "/etc/passwd", "http://host/out/a.exr", "out\\a.exr", "", "out/.."}) {
        EXPECT_TRUE(isUnsafeReviewName(name)) << name;
        EXPECT_FALSE(findReviewFile(files, name)) << name;
    }
    EXPECT_FALSE(isUnsafeReviewName("out/a.exr"));
}

}  // namespace
}  // namespace fluence::app
