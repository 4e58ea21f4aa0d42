// USD crate decompression (internal to the scene library): the LZ4 framing of OpenUSD's
// TfFastCompression, which every compressed crate section and array uses.
//
// Layout: one leading byte holding the chunk count. 0 means the rest of the buffer is a single
// LZ4 block; n > 0 means n chunks follow, each an int32 (little-endian) compressed size and then
// that many bytes of one LZ4 block. Each block decompresses to at most LZ4's maximum input size
// (~2 GiB). The output is the concatenation of the decompressed blocks.
//
// Every malformed input (empty buffer, chunk size past the end, an LZ4 block that does not
// decode, output longer than `maxOutput`) throws CrateFormatError; nothing is read out of bounds.
#pragma once

#include <cstddef>
#include <span>
#include <stdexcept>
#include <vector>

namespace fluence::usd::detail {

// What is wrong inside a crate file; the crate reader adds the file name.
class CrateFormatError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Decompresses `compressed` (TfFastCompression framing) into at most `maxOutput` bytes.
std::vector<char> decompressCrateBuffer(std::span<const char> compressed, std::size_t maxOutput);

}  // namespace fluence::usd::detail
