// Numbers and strings on binary std::iostreams, in the machine's own byte order, for files a
// machine writes and reads back itself (render checkpoints, core/film_state.h). Such a file is not
// portable between byte orders: its writer records a byte-order mark (kByteOrderMark) that its
// reader checks. Strings are a u32 length and their bytes. Reading past the end of the data, or a
// length beyond the caller's bound, throws BinaryReadError.
#pragma once

#include <cstdint>
#include <istream>
#include <ostream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>

namespace fluence {

class BinaryReadError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Written as a u32; reads back as itself only in the same byte order.
inline constexpr std::uint32_t kByteOrderMark = 0x01020304u;

template <typename T>
void writeBinary(std::ostream& out, const T* values, std::size_t count) {
    static_assert(std::is_trivially_copyable_v<T>);
    out.write(reinterpret_cast<const char*>(values), static_cast<std::streamsize>(sizeof(T) * count));
}
template <typename T>
void writeBinary(std::ostream& out, const T& value) {
    writeBinary(out, &value, 1);
}
inline void writeBinaryString(std::ostream& out, std::string_view text) {
    writeBinary(out, static_cast<std::uint32_t>(text.size()));
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
}

template <typename T>
void readBinary(std::istream& in, T* values, std::size_t count) {
    static_assert(std::is_trivially_copyable_v<T>);
    const auto bytes = static_cast<std::streamsize>(sizeof(T) * count);
    if (!in.read(reinterpret_cast<char*>(values), bytes) || in.gcount() != bytes)
        throw BinaryReadError("the data ends early");
}
template <typename T>
T readBinary(std::istream& in) {
    T value;
    readBinary(in, &value, 1);
    return value;
}
inline std::string readBinaryString(std::istream& in, std::uint32_t maxLength) {
    const auto length = readBinary<std::uint32_t>(in);
    if (length > maxLength)
        throw BinaryReadError("a string of " + std::to_string(length) + " bytes (at most " + std::to_string(maxLength) +
                              " expected)");
    std::string text(length, '\0');
    readBinary(in, text.data(), length);
    return text;
}

}  // namespace fluence
