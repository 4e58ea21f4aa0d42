// Atomic file replacement: readers see either the old file or the complete new one, never a
// partial write, and a failed write leaves nothing behind.
//
// The data is written to a temporary file in the same directory as the target (a hidden name such
// as ".out.exr.tmp-<pid>-<counter>", so nobody mistakes it for the result), flushed to disk, and
// renamed over the target (rename(2) is atomic within one file system). On any failure the
// temporary file is removed and OutputError is thrown, its message naming the target and the reason:
//   "cannot write /no/such/dir/x.exr: directory does not exist"
#pragma once

#include <functional>
#include <stdexcept>
#include <string>

namespace fluence::output {

// Thrown when an output file cannot be written. The message names the final path.
class OutputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Builds the OutputError message "cannot write <path>: <reason>".
OutputError outputError(const std::string& path, const std::string& reason);

class AtomicFile {
public:
    // Checks that the target's directory exists and that the target is not a directory, and picks
    // the temporary name (nothing is created yet). Throws OutputError otherwise.
    explicit AtomicFile(std::string finalPath);
    // Removes the temporary file unless commit() succeeded.
    ~AtomicFile();
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    const std::string& finalPath() const { return finalPath_; }
    // Where the writer must put the complete contents (the file need not exist yet).
    const std::string& tempPath() const { return tempPath_; }

    // Flushes the temporary file to disk and renames it to the final path. Throws OutputError
    // (after removing the temporary file) if it does not exist or cannot be renamed.
    void commit();
    // Removes the temporary file (if any) and throws OutputError("cannot write <final>: <reason>").
    [[noreturn]] void fail(const std::string& reason);

private:
    void removeTemp() noexcept;

    std::string finalPath_;
    std::string tempPath_;
    bool committed_ = false;
};

// Removes the temporary files of `finalPath` that processes no longer running left behind (a
// process killed while writing, e.g. by SIGKILL, cannot remove its own). Those of live processes
// are left alone. Errors are ignored: this is tidying.
void removeStaleTemporaries(const std::string& finalPath);

// Convenience: creates an AtomicFile for `finalPath`, calls write(tempPath) and commits. If `write`
// throws, the temporary file is removed and the error is rethrown as OutputError naming finalPath
// (an OutputError is rethrown unchanged).
void writeAtomically(const std::string& finalPath, const std::function<void(const std::string& tempPath)>& write);

}  // namespace fluence::output
