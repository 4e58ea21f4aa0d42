#include "output/atomic_file.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <system_error>
#include <utility>

namespace fluence::output {

namespace fs = std::filesystem;

namespace {

std::atomic<unsigned long> gTempCounter{0};

std::string errnoText(int err) { return std::error_code(err, std::generic_category()).message(); }

}  // namespace

OutputError outputError(const std::string& path, const std::string& reason) {
    return OutputError("cannot write " + path + ": " + reason);
}

AtomicFile::AtomicFile(std::string finalPath) : finalPath_(std::move(finalPath)) {
    if (finalPath_.empty()) throw OutputError("cannot write an empty path");
    const fs::path target(finalPath_);
    if (!target.has_filename()) throw outputError(finalPath_, "not a file name");
    fs::path dir = target.parent_path();
    if (dir.empty()) dir = ".";

    std::error_code ec;
    const auto dirStatus = fs::status(dir, ec);
    if (!fs::exists(dirStatus)) throw outputError(finalPath_, "directory does not exist");
    if (!fs::is_directory(dirStatus)) throw outputError(finalPath_, dir.string() + " is not a directory");
    if (fs::is_directory(fs::status(target, ec))) throw outputError(finalPath_, "is a directory");

    const unsigned long n = gTempCounter.fetch_add(1, std::memory_order_relaxed);
    // Appended piece by piece: `"." + std::string` trips GCC 12's false -Wrestrict (GCC bug 105329).
    std::string name(".");
    name += target.filename().string();
    name += ".tmp-";
    name += std::to_string(::getpid());
    name += '-';
    name += std::to_string(n);
    tempPath_ = (dir / name).string();
}

AtomicFile::~AtomicFile() {
    if (!committed_) removeTemp();
}

void AtomicFile::removeTemp() noexcept {
    std::error_code ec;
    fs::remove(tempPath_, ec);
}

void AtomicFile::fail(const std::string& reason) {
    removeTemp();
    throw outputError(finalPath_, reason);
}

void AtomicFile::commit() {
    if (committed_) return;
    // Flush the data before the rename, so that after a crash the final name holds either the old
    // or the complete new contents.
    const int fd = ::open(tempPath_.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) fail("temporary file " + tempPath_ + " was not written (" + errnoText(errno) + ")");
    const bool synced = ::fsync(fd) == 0;
    const int syncErr = errno;
    ::close(fd);
    if (!synced) fail("cannot flush " + tempPath_ + " to disk (" + errnoText(syncErr) + ")");

    if (std::rename(tempPath_.c_str(), finalPath_.c_str()) != 0) {
        const int err = errno;
        fail("cannot rename " + tempPath_ + " (" + errnoText(err) + ")");
    }
    committed_ = true;
}

void removeStaleTemporaries(const std::string& finalPath) {
    const fs::path target(finalPath);
    fs::path dir = target.parent_path();
    if (dir.empty()) dir = ".";
    std::string prefix(".");  // the AtomicFile constructor's naming (and its GCC 12 workaround)
    prefix += target.filename().string();
    prefix += ".tmp-";
    std::error_code ec;
    for (const fs::directory_entry& entry : fs::directory_iterator(dir, ec)) {
        const std::string name = entry.path().filename().string();
        if (!name.starts_with(prefix)) continue;
        const long pid = std::strtol(name.c_str() + prefix.size(), nullptr, 10);
        if (pid > 0 && ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH) fs::remove(entry.path(), ec);
    }
}

void writeAtomically(const std::string& finalPath, const std::function<void(const std::string& tempPath)>& write) {
    AtomicFile file(finalPath);
    try {
        write(file.tempPath());
    } catch (const OutputError&) {
        throw;  // ~AtomicFile removes the temporary file
    } catch (const std::exception& e) {
        file.fail(e.what());
    }
    file.commit();
}

}  // namespace fluence::output
