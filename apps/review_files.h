// The files `fluence review` serves: the EXR files, folders and frame sequences named on its
// command line, expanded once at start, and nothing else. A request names a file by the name it was
// listed under; names with `..`, absolute paths and URLs with a scheme are refused, and a folder's
// entries whose real path (symlinks resolved) leaves the folder are left out.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace fluence::app {

class ReviewInputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct ReviewFile {
    std::string name;      // the name the page and the URLs use: "render.exr", "out/beauty.0001.exr"
    std::string path;      // the real path on disk
    std::string sequence;  // for a frame of a sequence, the sequence's name ("out/beauty.####.exr"), else ""
    int frame = 0;         // its frame number
};

// Expands PATHs: an EXR file as itself; a folder as the EXR files under it; a frame sequence
// `name.$F4.exr` or `name.####.exr` (any number of #, or $F with an optional width) as the frames
// present. Frames of a sequence, and files in one folder named <prefix><digits>.exr that share the
// prefix and digit count, are grouped into a sequence, ordered by frame. Throws ReviewInputError
// naming the path when it does not exist, a pattern matches no file, or nothing is found at all.
std::vector<ReviewFile> expandReviewPaths(const std::vector<std::string>& paths);

// The file listed under `name`, or nothing when `name` is not a listed name or is unsafe
// (an absolute path, a `..` segment, a backslash, a scheme such as http:, a NUL).
std::optional<ReviewFile> findReviewFile(const std::vector<ReviewFile>& files, const std::string& name);

// True when `name` could never name a served file: see findReviewFile.
bool isUnsafeReviewName(const std::string& name);

}  // namespace fluence::app
