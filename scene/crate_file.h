// The structure of a USD crate file (.usdc, and .usd files starting "PXR-USDC"), internal to the
// scene library: OpenUSD's binary layer format, read without OpenUSD.
//
// A crate file is a bootstrap header (the magic "PXR-USDC", a version major.minor.patch and the
// offset of the table of contents), the value data, and the table of contents: named sections
// TOKENS (the token table, LZ4-compressed NUL-separated text), STRINGS (token indexes),
// FIELDS (a token index and a ValueRep per field), FIELDSETS (runs of field indexes, each run
// ended by ~0u), PATHS (the path tree, encoded as three compressed integer lists: path index,
// element token index (negative for properties) and jump (-1 child only, 0 sibling only, -2 leaf,
// n > 0 both: the sibling is n entries ahead)) and SPECS (path, field set and spec type per spec).
// This reader takes crate versions 0.0.1 to 0.11.x, as OpenUSD's crateFile.cpp reads them: since
// 0.4.0 the structural sections are compressed as above; before it they are plain vectors (a
// uint64 count, then the items): TOKENS a uint64 byte size and the NUL-separated text, FIELDS
// 16-byte records (4 bytes of padding, token index, ValueRep), FIELDSETS uint32 indexes, SPECS
// (path, field set, spec type) records, PATHS one header per path in pre-order (crate_file.cpp);
// in 0.0.1 spec records and path headers start with 4 bytes of padding. Value encodings that
// changed with the version are crate_values.h's.
//
// All multi-byte numbers are little-endian. Every offset, count and index is checked against the
// file before use: a damaged file throws CrateFormatError (crate_compression.h), never reads out
// of bounds. The file's bytes are shared (scene/mapped_file.h: a read-only mapping of the file, or
// bytes in memory), so values decoded later (crate_values.h's deferred arrays) keep them alive.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <vector>

#include "scene/crate_compression.h"
#include "scene/mapped_file.h"

namespace fluence::usd::detail {

struct CrateVersion {
    int major = 0, minor = 0, patch = 0;
    bool atLeast(int ma, int mi, int pa) const {
        return major != ma ? major > ma : minor != mi ? minor > mi : patch >= pa;
    }
    std::string str() const;
};

// A value as stored in a field: type enum, array/inlined/compressed bits and a 48-bit payload
// (the value itself when inlined, else the file offset of its data).
struct ValueRep {
    std::uint64_t bits = 0;
    int type() const { return static_cast<int>((bits >> 48) & 0xFF); }
    bool isArray() const { return (bits >> 63) & 1; }
    bool isInlined() const { return (bits >> 62) & 1; }
    bool isCompressed() const { return (bits >> 61) & 1; }
    std::uint64_t payload() const { return bits & ((std::uint64_t{1} << 48) - 1); }
};

// Sdf's spec types, as crate files number them.
enum class CrateSpecType : std::uint32_t {
    Attribute = 1,
    Connection = 2,
    Expression = 3,
    Mapper = 4,
    MapperArg = 5,
    Prim = 6,
    PseudoRoot = 7,
    Relationship = 8,
    RelationshipTarget = 9,
    Variant = 10,
    VariantSet = 11,
};

struct CrateField {
    std::uint32_t token = 0;  // the field's name
    ValueRep value;
};

struct CrateSpec {
    std::uint32_t path = 0;
    std::uint32_t fieldSet = 0;  // index of the first field index of its run in fieldSets
    CrateSpecType type = CrateSpecType::Prim;
};

// A bounds-checked little-endian reader over a span of the file.
class ByteReader {
public:
    ByteReader(std::span<const char> bytes, std::size_t position) : bytes_(bytes), position_(position) {
        if (position > bytes.size()) fail(position, 0);
    }

    template <class T>
    T read() {
        T value;
        std::memcpy(&value, take(sizeof(T)).data(), sizeof(T));
        return value;
    }
    std::span<const char> take(std::size_t size) {
        if (size > bytes_.size() - position_) fail(position_, size);
        std::span<const char> out = bytes_.subspan(position_, size);
        position_ += size;
        return out;
    }
    // Reads a count of items `itemSize` bytes each that must all fit in the rest of the span.
    std::size_t readCount(std::size_t itemSize);
    void seek(std::uint64_t position) {
        if (position > bytes_.size()) fail(position, 0);
        position_ = static_cast<std::size_t>(position);
    }
    std::size_t position() const { return position_; }
    std::span<const char> bytes() const { return bytes_; }

private:
    [[noreturn]] void fail(std::uint64_t at, std::uint64_t size) const;
    std::span<const char> bytes_;
    std::size_t position_ = 0;
};

// Throws the FileError a damaged crate file is reported with: "'<identifier>': damaged or
// unsupported USD crate file: <what>".
[[noreturn]] void throwDamagedCrateFile(const std::string& identifier, const std::string& what);

// A compressed integer list as crate sections store it: uint64 compressed size, then the bytes.
std::vector<std::int32_t> readCompressedInts32(ByteReader& reader, std::size_t count);
std::vector<std::int64_t> readCompressedInts64(ByteReader& reader, std::size_t count);

class CrateFile {
public:
    // Reads the bootstrap header and the structural sections of `file` (the whole file), named
    // `identifier` in the errors of values decoded later.
    CrateFile(SharedBytes file, std::string identifier);

    const CrateVersion& version() const { return version_; }
    const std::string& identifier() const { return identifier_; }
    std::span<const char> bytes() const { return bytes_; }
    const SharedBytes& sharedBytes() const { return file_; }
    // A reader at a file offset (a ValueRep payload).
    ByteReader readerAt(std::uint64_t offset) const { return ByteReader(bytes_, checkedOffset(offset)); }

    // Table lookups; an index out of range throws CrateFormatError naming `what`.
    const std::string& token(std::uint64_t index) const;
    const std::string& string(std::uint64_t index) const;  // STRINGS entry -> its token
    // "/World/Box.points", "/A{v=x}B"; "" for the empty path (an index the path tree leaves unset).
    const std::string& path(std::uint64_t index) const;

    const std::vector<CrateSpec>& specs() const { return specs_; }
    // The fields of a spec's field set, in file order.
    std::vector<const CrateField*> fieldsOf(const CrateSpec& spec) const;

private:
    struct Section {
        std::string name;
        std::uint64_t start = 0, size = 0;
    };
    std::uint64_t checkedOffset(std::uint64_t offset) const;
    const Section* section(const char* name) const;
    ByteReader sectionReader(const Section& section) const;
    void readTableOfContents(std::uint64_t offset);
    void readTokens();
    void readStrings();
    void readFields();
    void readFieldSets();
    void readPaths();
    void readPathTree(ByteReader& reader, std::uint64_t sectionStart);
    void readCompressedPathTree(ByteReader& reader, std::uint64_t pathCount, std::uint64_t sectionSize);
    // Sets path `index` to the child `element` (a token index) of path `parent` (-1: the root).
    void setPath(std::uint32_t index, std::int64_t parent, std::uint64_t element, bool isProperty);
    bool hasCompressedSections() const;  // crate 0.4.0 and later
    void readSpecs();

    SharedBytes file_;
    std::span<const char> bytes_;  // *file_
    std::string identifier_;
    CrateVersion version_;
    std::vector<Section> sections_;
    std::vector<std::string> tokens_;
    std::vector<std::uint32_t> strings_;
    std::vector<CrateField> fields_;
    std::vector<std::uint32_t> fieldSets_;
    std::vector<std::string> paths_;
    std::size_t pathTextSize_ = 0;
    std::vector<CrateSpec> specs_;
};

}  // namespace fluence::usd::detail
