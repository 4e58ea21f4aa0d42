#include "scene/crate_compression.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string>

#include <lz4.h>

namespace fluence::usd::detail {

namespace {

// Decompresses one LZ4 block into `out` (at `written`), returning the bytes produced.
std::size_t decompressBlock(std::span<const char> block, std::vector<char>& out, std::size_t written) {
    std::size_t room = out.size() - written;
    if (block.size() > static_cast<std::size_t>(LZ4_MAX_INPUT_SIZE))
        throw CrateFormatError("an LZ4 block of " + std::to_string(block.size()) + " bytes is too large");
    int capacity = static_cast<int>(std::min<std::size_t>(room, LZ4_MAX_INPUT_SIZE));
    int produced = LZ4_decompress_safe(block.data(), out.data() + written, static_cast<int>(block.size()), capacity);
    if (produced < 0) throw CrateFormatError("corrupt LZ4 data (error " + std::to_string(produced) + ")");
    return static_cast<std::size_t>(produced);
}

}  // namespace

std::vector<char> decompressCrateBuffer(std::span<const char> compressed, std::size_t maxOutput) {
    if (compressed.empty()) throw CrateFormatError("empty compressed buffer");
    // LZ4 expands a block at most ~255 times: a larger claimed size is not allocated.
    std::vector<char> out(std::min(maxOutput, compressed.size() * 256 + 64));
    auto chunks = static_cast<unsigned char>(compressed[0]);
    std::span<const char> rest = compressed.subspan(1);
    std::size_t written = 0;
    if (chunks == 0) {
        written = decompressBlock(rest, out, 0);
    } else {
        for (unsigned i = 0; i < chunks; ++i) {
            std::int32_t size = 0;
            if (rest.size() < sizeof size) throw CrateFormatError("compressed chunk header past the end of its buffer");
            std::memcpy(&size, rest.data(), sizeof size);
            rest = rest.subspan(sizeof size);
            if (size < 0 || static_cast<std::size_t>(size) > rest.size())
                throw CrateFormatError("compressed chunk of " + std::to_string(size) +
                                       " bytes past the end of its buffer");
            written += decompressBlock(rest.first(static_cast<std::size_t>(size)), out, written);
            rest = rest.subspan(static_cast<std::size_t>(size));
        }
    }
    out.resize(written);
    return out;
}

}  // namespace fluence::usd::detail
