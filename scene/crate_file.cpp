#include "scene/crate_file.h"

#include <cstdlib>
#include <utility>

#include "scene/crate_integer_coding.h"
#include "scene/namespace_remap.h"
#include "scene/usda_parser.h"

namespace fluence::usd::detail {

namespace {

constexpr std::uint32_t kFieldSetEnd = ~0u;
constexpr std::size_t kBootstrapSize = 88;  // magic, version[8], tocOffset, reserved int64[8]
constexpr std::size_t kSectionNameSize = 16;
// The most integers a byte of a compressed integer list can hold: 4 two-bit codes per byte, LZ4
// expanding at most ~255 times. Larger counts are damage, rejected before anything is allocated.
constexpr std::uint64_t kMaxIntsPerByte = 1024;
constexpr std::size_t kMaxPathText = std::size_t{1} << 28;  // bounds what a damaged path tree can allocate

std::string describeOffset(std::uint64_t at) { return "offset " + std::to_string(at); }

}  // namespace

std::string CrateVersion::str() const {
    return std::to_string(major) + "." + std::to_string(minor) + "." + std::to_string(patch);
}

void ByteReader::fail(std::uint64_t at, std::uint64_t size) const {
    throw CrateFormatError("data at " + describeOffset(at) + (size ? " (" + std::to_string(size) + " bytes)" : "") +
                           " lies past the end of its section (" + std::to_string(bytes_.size()) + " bytes)");
}

void throwDamagedCrateFile(const std::string& identifier, const std::string& what) {
    throw FileError("'" + identifier + "': damaged or unsupported USD crate file: " + what);
}

std::size_t ByteReader::readCount(std::size_t itemSize) {
    auto count = read<std::uint64_t>();
    std::size_t left = bytes_.size() - position_;
    if (itemSize != 0 && count > left / itemSize)
        throw CrateFormatError("a count of " + std::to_string(count) + " items at " +
                               describeOffset(position_ - sizeof count) + " runs past the end of its data");
    return static_cast<std::size_t>(count);
}

namespace {

template <class Int, class Decompress>
std::vector<Int> readCompressed(ByteReader& reader, std::size_t count, Decompress decompress) {
    auto size = reader.read<std::uint64_t>();
    if (size > reader.bytes().size()) throw CrateFormatError("compressed integers larger than their section");
    return decompress(reader.take(static_cast<std::size_t>(size)), count);
}

}  // namespace

std::vector<std::int32_t> readCompressedInts32(ByteReader& reader, std::size_t count) {
    return readCompressed<std::int32_t>(reader, count, decompressIntegers32);
}

std::vector<std::int64_t> readCompressedInts64(ByteReader& reader, std::size_t count) {
    return readCompressed<std::int64_t>(reader, count, decompressIntegers64);
}

// ---- CrateFile ---------------------------------------------------------------------------------

CrateFile::CrateFile(SharedBytes file, std::string identifier)
    : file_(std::move(file)), bytes_(file_->data(), file_->size()), identifier_(std::move(identifier)) {
    if (bytes_.size() < 8 || std::memcmp(bytes_.data(), "PXR-USDC", 8) != 0)
        throw CrateFormatError("not a USD crate file (no PXR-USDC header)");
    if (bytes_.size() < kBootstrapSize)
        throw CrateFormatError("the file (" + std::to_string(bytes_.size()) + " bytes) is too short for the " +
                               std::to_string(kBootstrapSize) + "-byte crate header");
    ByteReader boot(bytes_, 8);
    version_.major = boot.read<std::uint8_t>();
    version_.minor = boot.read<std::uint8_t>();
    version_.patch = boot.read<std::uint8_t>();
    boot.seek(16);
    auto tocOffset = boot.read<std::uint64_t>();
    if (!version_.atLeast(0, 0, 1) || version_.atLeast(0, 12, 0))
        throw CrateFormatError("crate version " + version_.str() +
                               " is not supported (this reader takes versions 0.0.1 to 0.11.x)");
    readTableOfContents(tocOffset);
    readTokens();
    readStrings();
    readFields();
    readFieldSets();
    readPaths();
    readSpecs();
}

bool CrateFile::hasCompressedSections() const { return version_.atLeast(0, 4, 0); }

std::uint64_t CrateFile::checkedOffset(std::uint64_t offset) const {
    if (offset >= bytes_.size())
        throw CrateFormatError("value at " + describeOffset(offset) + " lies past the end of the file (" +
                               std::to_string(bytes_.size()) + " bytes)");
    return offset;
}

void CrateFile::readTableOfContents(std::uint64_t offset) {
    if (offset >= bytes_.size())
        throw CrateFormatError("table of contents at " + describeOffset(offset) +
                               " lies past the end of the file (truncated?)");
    ByteReader reader(bytes_, static_cast<std::size_t>(offset));
    std::size_t count = reader.readCount(kSectionNameSize + 16);
    for (std::size_t i = 0; i < count; ++i) {
        std::span<const char> name = reader.take(kSectionNameSize);
        Section section;
        section.name.assign(name.data(), strnlen(name.data(), kSectionNameSize));
        section.start = reader.read<std::uint64_t>();
        section.size = reader.read<std::uint64_t>();
        if (section.start > bytes_.size() || section.size > bytes_.size() - section.start)
            throw CrateFormatError("section " + section.name + " (" + describeOffset(section.start) + ", " +
                                   std::to_string(section.size) + " bytes) lies past the end of the file");
        sections_.push_back(std::move(section));
    }
}

const CrateFile::Section* CrateFile::section(const char* name) const {
    for (const Section& s : sections_)
        if (s.name == name) return &s;
    return nullptr;
}

ByteReader CrateFile::sectionReader(const Section& section) const {
    return ByteReader(std::span<const char>(bytes_).subspan(section.start, section.size), 0);
}

void CrateFile::readTokens() {
    const Section* tokens = section("TOKENS");
    if (!tokens) return;
    ByteReader reader = sectionReader(*tokens);
    auto count = reader.read<std::uint64_t>();
    std::vector<char> text;
    if (hasCompressedSections()) {
        auto size = reader.read<std::uint64_t>();
        auto compressedSize = reader.read<std::uint64_t>();
        if (compressedSize > tokens->size) throw CrateFormatError("TOKENS section: compressed size past its end");
        text = decompressCrateBuffer(reader.take(static_cast<std::size_t>(compressedSize)),
                                     static_cast<std::size_t>(size));
        if (text.size() != size) throw CrateFormatError("TOKENS section: decompressed size differs from the header");
    } else {
        std::span<const char> plain = reader.take(reader.readCount(1));
        text.assign(plain.begin(), plain.end());
    }
    if (count > text.size()) throw CrateFormatError("TOKENS section: more tokens than characters");
    tokens_.reserve(static_cast<std::size_t>(count));
    std::size_t at = 0;
    while (tokens_.size() < count) {
        const char* start = text.data() + at;
        const void* end = std::memchr(start, '\0', text.size() - at);
        if (!end)
            throw CrateFormatError("TOKENS section: " + std::to_string(count) + " tokens claimed, " +
                                   std::to_string(tokens_.size()) + " found");
        std::size_t length = static_cast<const char*>(end) - start;
        tokens_.emplace_back(start, length);
        at += length + 1;
    }
}

void CrateFile::readStrings() {
    const Section* strings = section("STRINGS");
    if (!strings) return;
    ByteReader reader = sectionReader(*strings);
    strings_.resize(reader.readCount(sizeof(std::uint32_t)));
    for (std::uint32_t& s : strings_) {
        s = reader.read<std::uint32_t>();
        token(s);  // range check
    }
}

void CrateFile::readFields() {
    const Section* fields = section("FIELDS");
    if (!fields) return;
    ByteReader reader = sectionReader(*fields);
    if (!hasCompressedSections()) {
        // A vector of 16-byte records: 4 bytes of padding, the token index, the ValueRep.
        fields_.resize(reader.readCount(16));
        for (CrateField& field : fields_) {
            reader.read<std::uint32_t>();
            field.token = reader.read<std::uint32_t>();
            token(field.token);
            field.value.bits = reader.read<std::uint64_t>();
        }
        return;
    }
    auto count = reader.read<std::uint64_t>();
    if (count > fields->size * kMaxIntsPerByte) throw CrateFormatError("FIELDS section: field count too large");
    std::vector<std::int32_t> names = readCompressedInts32(reader, static_cast<std::size_t>(count));
    auto repsSize = reader.read<std::uint64_t>();
    if (repsSize > fields->size) throw CrateFormatError("FIELDS section: value size past its end");
    std::vector<char> reps = decompressCrateBuffer(reader.take(static_cast<std::size_t>(repsSize)),
                                                   static_cast<std::size_t>(count) * sizeof(std::uint64_t));
    if (reps.size() != count * sizeof(std::uint64_t)) throw CrateFormatError("FIELDS section: values end early");
    fields_.resize(static_cast<std::size_t>(count));
    for (std::size_t i = 0; i < fields_.size(); ++i) {
        fields_[i].token = static_cast<std::uint32_t>(names[i]);
        token(fields_[i].token);
        std::memcpy(&fields_[i].value.bits, reps.data() + i * sizeof(std::uint64_t), sizeof(std::uint64_t));
    }
}

void CrateFile::readFieldSets() {
    const Section* fieldSets = section("FIELDSETS");
    if (!fieldSets) return;
    ByteReader reader = sectionReader(*fieldSets);
    if (hasCompressedSections()) {
        auto count = reader.read<std::uint64_t>();
        if (count > fieldSets->size * kMaxIntsPerByte) throw CrateFormatError("FIELDSETS section: count too large");
        std::vector<std::int32_t> indexes = readCompressedInts32(reader, static_cast<std::size_t>(count));
        fieldSets_.assign(indexes.begin(), indexes.end());
    } else {
        fieldSets_.resize(reader.readCount(sizeof(std::uint32_t)));
        for (std::uint32_t& index : fieldSets_) index = reader.read<std::uint32_t>();
    }
    for (std::uint32_t index : fieldSets_)
        if (index != kFieldSetEnd && index >= fields_.size())
            throw CrateFormatError("FIELDSETS section: field index " + std::to_string(index) + " out of range");
    if (!fieldSets_.empty() && fieldSets_.back() != kFieldSetEnd)
        throw CrateFormatError("FIELDSETS section: the last field set is not terminated");
}

void CrateFile::readPaths() {
    const Section* paths = section("PATHS");
    if (!paths) return;
    ByteReader reader = sectionReader(*paths);
    auto pathCount = reader.read<std::uint64_t>();
    if (hasCompressedSections()) return readCompressedPathTree(reader, pathCount, paths->size);
    // Every path takes a header of at least 12 bytes.
    if (pathCount > paths->size / 12 + 1) throw CrateFormatError("PATHS section: path count too large");
    paths_.assign(static_cast<std::size_t>(pathCount), std::string());
    readPathTree(reader, paths->start);
}

void CrateFile::setPath(std::uint32_t index, std::int64_t parent, std::uint64_t element, bool isProperty) {
    if (index >= paths_.size())
        throw CrateFormatError("PATHS section: path index " + std::to_string(index) + " out of range");
    if (!paths_[index].empty()) throw CrateFormatError("PATHS section: the path tree is malformed");
    if (parent < 0) {
        paths_[index] = "/";
    } else {
        const std::string& name = token(element);
        const std::string& base = paths_[static_cast<std::size_t>(parent)];
        if (isProperty)
            paths_[index] = base + "." + name;
        else if (name.starts_with("{") || name.starts_with("[") || name.starts_with("."))
            paths_[index] = base + name;  // a variant selection, target or property element
        else
            paths_[index] = childPrimPath(base, name);
    }
    pathTextSize_ += paths_[index].size();
    if (pathTextSize_ > kMaxPathText)
        throw CrateFormatError("PATHS section: the paths add up to more than " + std::to_string(kMaxPathText) +
                               " bytes");
}

// Before 0.4.0: the tree in pre-order, one header per path (4 bytes of padding in 0.0.1, the path
// index, the element token index, bits: 1 has a child, 2 has a sibling, 4 is a property), a
// header with both a child and a sibling followed by the sibling's file offset (int64).
void CrateFile::readPathTree(ByteReader& reader, std::uint64_t sectionStart) {
    constexpr std::uint8_t kHasChild = 1, kHasSibling = 2, kIsProperty = 4;
    const bool padded = !version_.atLeast(0, 1, 0);
    // (section offset, parent path index or -1) of subtrees still to read: iterative, and every
    // header sets a new path (setPath), so a damaged tree ends after at most pathCount headers.
    std::vector<std::pair<std::size_t, std::int64_t>> pending{{reader.position(), -1}};
    while (!pending.empty()) {
        auto [at, parent] = pending.back();
        pending.pop_back();
        reader.seek(at);
        while (true) {
            if (padded) reader.read<std::uint32_t>();
            auto index = reader.read<std::uint32_t>();
            auto element = reader.read<std::uint32_t>();
            auto bits = reader.read<std::uint8_t>();
            reader.take(3);  // the header's trailing padding
            setPath(index, parent, element, bits & kIsProperty);
            bool hasChild = bits & kHasChild, hasSibling = bits & kHasSibling;
            if (hasChild && hasSibling) {
                auto sibling = reader.read<std::int64_t>();
                if (sibling < static_cast<std::int64_t>(sectionStart))
                    throw CrateFormatError("PATHS section: a sibling lies outside the section");
                pending.emplace_back(static_cast<std::size_t>(sibling - static_cast<std::int64_t>(sectionStart)),
                                     parent);
            }
            if (hasChild) parent = index;
            if (!hasChild && !hasSibling) break;
        }
    }
}

void CrateFile::readCompressedPathTree(ByteReader& reader, std::uint64_t pathCount, std::uint64_t sectionSize) {
    auto encodedCount = reader.read<std::uint64_t>();
    // Every path but the empty one is in the encoded tree.
    if (encodedCount > sectionSize * kMaxIntsPerByte || pathCount > encodedCount + 1)
        throw CrateFormatError("PATHS section: path count too large");
    std::size_t n = static_cast<std::size_t>(encodedCount);
    std::vector<std::int32_t> pathIndexes = readCompressedInts32(reader, n);
    std::vector<std::int32_t> elements = readCompressedInts32(reader, n);
    std::vector<std::int32_t> jumps = readCompressedInts32(reader, n);
    paths_.assign(static_cast<std::size_t>(pathCount), std::string());

    std::vector<bool> visited(n, false);
    // (encoded index, parent path index or -1) of subtrees still to walk: iterative, so a deep or
    // cyclic tree in a damaged file cannot overflow the stack or loop.
    std::vector<std::pair<std::size_t, std::int64_t>> pending;
    if (n > 0) pending.emplace_back(0, -1);
    while (!pending.empty()) {
        auto [i, parent] = pending.back();
        pending.pop_back();
        while (true) {
            if (i >= n || visited[i]) throw CrateFormatError("PATHS section: the path tree is malformed");
            visited[i] = true;
            auto index = static_cast<std::uint32_t>(pathIndexes[i]);
            std::int64_t element = elements[i];
            setPath(index, parent, static_cast<std::uint64_t>(std::llabs(element)), element < 0);
            std::int32_t jump = jumps[i];
            bool hasChild = jump > 0 || jump == -1;
            bool hasSibling = jump >= 0;
            if (hasChild && hasSibling) {
                std::int64_t sibling = static_cast<std::int64_t>(i) + jump;
                pending.emplace_back(static_cast<std::size_t>(sibling), parent);
            }
            if (hasChild) parent = index;
            if (!hasChild && !hasSibling) break;
            ++i;
        }
    }
}

void CrateFile::readSpecs() {
    const Section* specs = section("SPECS");
    if (!specs) return;
    ByteReader reader = sectionReader(*specs);
    std::vector<std::int32_t> paths, fieldSets, types;
    if (hasCompressedSections()) {
        auto count = reader.read<std::uint64_t>();
        if (count > specs->size * kMaxIntsPerByte) throw CrateFormatError("SPECS section: spec count too large");
        std::size_t n = static_cast<std::size_t>(count);
        paths = readCompressedInts32(reader, n);
        fieldSets = readCompressedInts32(reader, n);
        types = readCompressedInts32(reader, n);
    } else {
        // A vector of records: path, field set and spec type indexes, after 4 bytes of padding in 0.0.1.
        const bool padded = !version_.atLeast(0, 1, 0);
        std::size_t n = reader.readCount(padded ? 16 : 12);
        for (std::size_t i = 0; i < n; ++i) {
            if (padded) reader.read<std::uint32_t>();
            paths.push_back(reader.read<std::int32_t>());
            fieldSets.push_back(reader.read<std::int32_t>());
            types.push_back(reader.read<std::int32_t>());
        }
    }
    const std::size_t n = paths.size();
    specs_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        CrateSpec& spec = specs_[i];
        spec.path = static_cast<std::uint32_t>(paths[i]);
        path(spec.path);
        spec.fieldSet = static_cast<std::uint32_t>(fieldSets[i]);
        if (spec.fieldSet >= fieldSets_.size() && !(spec.fieldSet == 0 && fieldSets_.empty()))
            throw CrateFormatError("SPECS section: field set " + std::to_string(spec.fieldSet) + " out of range");
        auto type = static_cast<std::uint32_t>(types[i]);
        if (type < 1 || type > 11) throw CrateFormatError("SPECS section: unknown spec type " + std::to_string(type));
        spec.type = static_cast<CrateSpecType>(type);
    }
}

const std::string& CrateFile::token(std::uint64_t index) const {
    if (index >= tokens_.size())
        throw CrateFormatError("token index " + std::to_string(index) + " out of range (" +
                               std::to_string(tokens_.size()) + " tokens)");
    return tokens_[static_cast<std::size_t>(index)];
}

const std::string& CrateFile::string(std::uint64_t index) const {
    if (index >= strings_.size())
        throw CrateFormatError("string index " + std::to_string(index) + " out of range (" +
                               std::to_string(strings_.size()) + " strings)");
    return tokens_[strings_[static_cast<std::size_t>(index)]];
}

const std::string& CrateFile::path(std::uint64_t index) const {
    if (index >= paths_.size())
        throw CrateFormatError("path index " + std::to_string(index) + " out of range (" +
                               std::to_string(paths_.size()) + " paths)");
    return paths_[static_cast<std::size_t>(index)];
}

std::vector<const CrateField*> CrateFile::fieldsOf(const CrateSpec& spec) const {
    std::vector<const CrateField*> out;
    for (std::size_t i = spec.fieldSet; i < fieldSets_.size() && fieldSets_[i] != kFieldSetEnd; ++i)
        out.push_back(&fields_[fieldSets_[i]]);
    return out;
}

}  // namespace fluence::usd::detail
