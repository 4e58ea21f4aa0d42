// Tests for output/atomic_file.h: all-or-nothing replacement, clean failure.
#include "output/atomic_file.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>
#include "tests/support/temp_dir.h"

namespace {

using fluence::output::AtomicFile;
using fluence::output::OutputError;
using fluence::output::writeAtomically;
namespace fs = std::filesystem;

using fluence::test::TempDir;

void writeText(const std::string& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
}

std::string readText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(AtomicFile, WritesThroughHiddenTempAndRenames) {
    TempDir dir("fluence_atomic_test");
    const std::string target = dir.file("out.exr");
    AtomicFile file(target);
    EXPECT_EQ(file.finalPath(), target);
    const std::string tempName = fs::path(file.tempPath()).filename().string();
    EXPECT_EQ(fs::path(file.tempPath()).parent_path(), fs::path(target).parent_path());
    EXPECT_EQ(tempName.rfind(".out.exr.tmp-" + std::to_string(::getpid()) + "-", 0), 0u) << tempName;
    EXPECT_TRUE(dir.list().empty());  // nothing is created up front

    writeText(file.tempPath(), "new contents");
    EXPECT_EQ(dir.list(), std::vector<std::string>{tempName});
    file.commit();
    EXPECT_EQ(dir.list(), std::vector<std::string>{"out.exr"});
    EXPECT_EQ(readText(target), "new contents");
}

TEST(AtomicFile, TempNamesAreUnique) {
    TempDir dir("fluence_atomic_test");
    AtomicFile a(dir.file("x.png"));
    AtomicFile b(dir.file("x.png"));
    EXPECT_NE(a.tempPath(), b.tempPath());
}

TEST(AtomicFile, MissingDirectoryThrowsNamingPathAndLeavesNothing) {
    const std::string target = "/no/such/dir/x.exr";
    try {
        AtomicFile file(target);
        FAIL() << "expected OutputError";
    } catch (const OutputError& e) {
        EXPECT_EQ(std::string(e.what()), "cannot write /no/such/dir/x.exr: directory does not exist");
    }
    EXPECT_FALSE(fs::exists("/no/such/dir"));
}

TEST(AtomicFile, TargetThatIsADirectoryThrows) {
    TempDir dir("fluence_atomic_test");
    fs::create_directory(dir.file("sub"));
    EXPECT_THROW(AtomicFile(dir.file("sub")), OutputError);
    EXPECT_THROW(AtomicFile(""), OutputError);
}

TEST(AtomicFile, FailureMidwayKeepsOldFileAndRemovesTemp) {
    TempDir dir("fluence_atomic_test");
    const std::string target = dir.file("render.exr");
    writeText(target, "old good file");
    try {
        writeAtomically(target, [](const std::string& temp) {
            writeText(temp, "half a fi");
            throw std::runtime_error("disk on fire");
        });
        FAIL() << "expected OutputError";
    } catch (const OutputError& e) {
        EXPECT_EQ(std::string(e.what()), "cannot write " + target + ": disk on fire");
    }
    EXPECT_EQ(dir.list(), std::vector<std::string>{"render.exr"});
    EXPECT_EQ(readText(target), "old good file");
}

TEST(AtomicFile, AbandonedWithoutCommitRemovesTemp) {
    TempDir dir("fluence_atomic_test");
    const std::string target = dir.file("a.png");
    writeText(target, "old");
    {
        AtomicFile file(target);
        writeText(file.tempPath(), "partial");
    }
    EXPECT_EQ(dir.list(), std::vector<std::string>{"a.png"});
    EXPECT_EQ(readText(target), "old");
}

TEST(AtomicFile, CommitWithoutTempFileFails) {
    TempDir dir("fluence_atomic_test");
    AtomicFile file(dir.file("never.exr"));
    EXPECT_THROW(file.commit(), OutputError);
    EXPECT_TRUE(dir.list().empty());
}

TEST(AtomicFile, RenameFailureRemovesTemp) {
    // The final name becomes a non-empty directory after the AtomicFile was created: rename(2)
    // fails (deterministically, even as root) after the data was written.
    TempDir dir("fluence_atomic_test");
    const std::string target = dir.file("late.exr");
    AtomicFile file(target);
    writeText(file.tempPath(), "data");
    fs::create_directory(target);
    writeText(target + "/keep", "x");
    try {
        file.commit();
        FAIL() << "expected OutputError";
    } catch (const OutputError& e) {
        EXPECT_EQ(std::string(e.what()).rfind("cannot write " + target + ": cannot rename", 0), 0u) << e.what();
    }
    EXPECT_EQ(dir.list(), std::vector<std::string>{"late.exr"});
    EXPECT_TRUE(fs::is_directory(target));
}

TEST(AtomicFile, RelativePathUsesCurrentDirectory) {
    TempDir dir("fluence_atomic_test");
    const fs::path old = fs::current_path();
    fs::current_path(dir.file(""));
    try {
        writeAtomically("rel.txt", [](const std::string& temp) {
            EXPECT_EQ(fs::path(temp).parent_path(), fs::path("."));
            writeText(temp, "ok");
        });
    } catch (...) {
        fs::current_path(old);
        throw;
    }
    fs::current_path(old);
    EXPECT_EQ(dir.list(), std::vector<std::string>{"rel.txt"});
}

}  // namespace
