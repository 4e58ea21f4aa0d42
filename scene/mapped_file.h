// Files read in place: a whole file memory-mapped read-only, shared by everything that reads from
// it (a USDZ package's entries, a crate layer's values still to be decoded) and unmapped when the
// last holder lets go.
//
// Conventions:
//   - The bytes are a std::string_view over the mapping (empty files are an empty view, not
//     mapped). Readers keep their own bounds checks against its size.
//   - The file's size is read again after mapping: a file that shrank in between (still being
//     written, or replaced) is a FileError, not a view past its end.
//   - A file truncated AFTER that check is not protected against: touching a page past its new end
//     raises SIGBUS, as with any memory-mapped file. Files are expected not to be truncated in
//     place while Fluence reads them (editors that save by writing a new file and renaming it over
//     the old one are safe: the mapping keeps the old file's pages).
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace fluence::usd {

using SharedBytes = std::shared_ptr<const std::string_view>;

// Maps the regular file at `path`; throws FileError naming it when it cannot be opened or mapped.
SharedBytes mapFile(const std::string& path);

// Bytes already in memory, held as a mapping would be.
SharedBytes holdBytes(std::vector<char> bytes);

}  // namespace fluence::usd
