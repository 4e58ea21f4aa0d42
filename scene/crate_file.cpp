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
    if (!version_.atLeast(0, 4, 0) || version_.atLeast(0, 12, 0))
        throw CrateFormatError("crate version " + version_.str() +
                               " is not supported (this reader takes versions 0.4.0 to 0.11.x)");
    readTableOfContents(tocOffset);
    readTokens();
    readStrings();
    readFields();
    readFieldSets();
    readPaths();
    readSpecs();
}

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
    auto size = reader.read<std::uint64_t>();
    auto compressedSize = reader.read<std::uint64_t>();
    if (compressedSize > tokens->size) throw CrateFormatError("TOKENS section: compressed size past its end");
    if (count > size) throw CrateFormatError("TOKENS section: more tokens than characters");
    std::vector<char> text = decompressCrateBuffer(reader.take(static_cast<std::size_t>(compressedSize)),
                                                   static_cast<std::size_t>(size));
    if (text.size() != size) throw CrateFormatError("TOKENS section: decompressed size differs from the header");
    tokens_.reserve(static_cast<std::size_t>(count));
    std::size_t at = 0;
    while (tokens_.size() < count) {
        const char* start = text.data() + at;
        const void* end = std::memchr(start, '\0', text.size() - at);
        if (!end) throw CrateFormatError("TOKENS section: " + std::to_string(count) + " tokens claimed, " +
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
    auto count = reader.read<std::uint64_t>();
    if (count > fieldSets->size * kMaxIntsPerByte) throw CrateFormatError("FIELDSETS section: count too large");
    std::vector<std::int32_t> indexes = readCompressedInts32(reader, static_cast<std::size_t>(count));
    fieldSets_.assign(indexes.begin(), indexes.end());
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
    auto encodedCount = reader.read<std::uint64_t>();
    // Every path but the empty one is in the encoded tree.
    if (encodedCount > paths->size * kMaxIntsPerByte || pathCount > encodedCount + 1)
        throw CrateFormatError("PATHS section: path count too large");
    std::size_t n = static_cast<std::size_t>(encodedCount);
    std::vector<std::int32_t> pathIndexes = readCompressedInts32(reader, n);
    std::vector<std::int32_t> elements = readCompressedInts32(reader, n);
    std::vector<std::int32_t> jumps = readCompressedInts32(reader, n);
    paths_.assign(static_cast<std::size_t>(pathCount), std::string());

    auto fail = [](const std::string& what) { throw CrateFormatError("PATHS section: " + what); };
    std::vector<bool> visited(n, false);
    std::size_t textSize = 0;
    // (encoded index, parent path index or -1) of subtrees still to walk: iterative, so a deep or
    // cyclic tree in a damaged file cannot overflow the stack or loop.
    std::vector<std::pair<std::size_t, std::int64_t>> pending;
    if (n > 0) pending.emplace_back(0, -1);
    while (!pending.empty()) {
        auto [i, parent] = pending.back();
        pending.pop_back();
        while (true) {
            if (i >= n || visited[i]) fail("the path tree is malformed");
            visited[i] = true;
            auto index = static_cast<std::uint32_t>(pathIndexes[i]);
            if (index >= paths_.size()) fail("path index " + std::to_string(index) + " out of range");
            if (parent < 0) {
                paths_[index] = "/";
            } else {
                std::int64_t element = elements[i];
                const std::string& name = token(static_cast<std::uint64_t>(std::llabs(element)));
                const std::string& base = paths_[static_cast<std::size_t>(parent)];
                if (element < 0)
                    paths_[index] = base + "." + name;
                else if (name.starts_with("{") || name.starts_with("[") || name.starts_with("."))
                    paths_[index] = base + name;  // a variant selection, target or property element
                else
                    paths_[index] = childPrimPath(base, name);
            }
            textSize += paths_[index].size();
            if (textSize > kMaxPathText) fail("the paths add up to more than " + std::to_string(kMaxPathText) + " bytes");
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
    auto count = reader.read<std::uint64_t>();
    if (count > specs->size * kMaxIntsPerByte) throw CrateFormatError("SPECS section: spec count too large");
    std::size_t n = static_cast<std::size_t>(count);
    std::vector<std::int32_t> paths = readCompressedInts32(reader, n);
    std::vector<std::int32_t> fieldSets = readCompressedInts32(reader, n);
    std::vector<std::int32_t> types = readCompressedInts32(reader, n);
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
