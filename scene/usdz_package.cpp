#include "scene/usdz_package.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <filesystem>

#include "scene/mapped_file.h"
#include "scene/usda_parser.h"

namespace fluence::usd {

namespace {

// Zip record signatures and fixed sizes (PKWARE APPNOTE 4.3).
constexpr std::uint32_t kEndOfDirectorySignature = 0x06054b50;
constexpr std::uint32_t kZip64LocatorSignature = 0x07064b50;
constexpr std::uint32_t kDirectoryEntrySignature = 0x02014b50;
constexpr std::uint32_t kLocalHeaderSignature = 0x04034b50;
constexpr std::size_t kEndOfDirectorySize = 22;
constexpr std::size_t kZip64LocatorSize = 20;
constexpr std::size_t kDirectoryEntrySize = 46;
constexpr std::size_t kLocalHeaderSize = 30;
constexpr std::size_t kMaxCommentSize = 0xFFFF;

// Little-endian fields of the archive, each read checked against its end.
class ArchiveReader {
public:
    ArchiveReader(std::string_view data, const std::string& path) : data_(data), path_(path) {}

    [[noreturn]] void fail(const std::string& what) const { throw FileError("'" + path_ + "': " + what); }

    bool fits(std::size_t at, std::size_t size) const { return at <= data_.size() && size <= data_.size() - at; }

    std::uint32_t field(std::size_t at, std::size_t bytes, const char* record) const {
        if (!fits(at, bytes)) fail(std::string("truncated zip archive (") + record + " runs past the end of the file)");
        std::uint32_t value = 0;
        for (std::size_t i = bytes; i-- > 0;) value = value << 8 | static_cast<unsigned char>(data_[at + i]);
        return value;
    }
    std::uint32_t u16(std::size_t at, const char* record) const { return field(at, 2, record); }
    std::uint32_t u32(std::size_t at, const char* record) const { return field(at, 4, record); }

    // The end-of-central-directory record: the last one, searched back over a possible comment.
    std::size_t endOfDirectory() const {
        if (data_.size() < kEndOfDirectorySize)
            fail("not a zip archive (too short for an end-of-central-directory record)");
        std::size_t last = data_.size() - kEndOfDirectorySize;
        std::size_t first = last > kMaxCommentSize ? last - kMaxCommentSize : 0;
        for (std::size_t at = last + 1; at-- > first;)
            if (u32(at, "end of central directory") == kEndOfDirectorySignature &&
                at + kEndOfDirectorySize + u16(at + 20, "end of central directory") == data_.size())
                return at;
        fail("not a zip archive (no end-of-central-directory record; truncated?)");
    }

    std::vector<UsdzPackage::Entry> entries() const {
        std::size_t end = endOfDirectory();
        if (end >= kZip64LocatorSize && u32(end - kZip64LocatorSize, "zip64 locator") == kZip64LocatorSignature)
            fail("zip64 archives are not supported");
        if (u16(end + 4, "end of central directory") != 0 || u16(end + 6, "end of central directory") != 0)
            fail("multi-disk zip archives are not supported");
        std::uint32_t count = u16(end + 10, "end of central directory");
        std::uint32_t directorySize = u32(end + 12, "end of central directory");
        std::uint32_t directoryOffset = u32(end + 16, "end of central directory");
        if (count == 0xFFFF || directorySize == 0xFFFFFFFF || directoryOffset == 0xFFFFFFFF)
            fail("zip64 archives are not supported");
        if (!fits(directoryOffset, directorySize) || std::size_t(directoryOffset) + directorySize > end)
            fail("damaged zip archive (the central directory lies outside the file)");
        std::vector<UsdzPackage::Entry> result;
        std::size_t at = directoryOffset;
        for (std::uint32_t i = 0; i < count; ++i)
            at = readEntry(at, std::size_t(directoryOffset) + directorySize, result);
        return result;
    }

private:
    // Reads the central directory entry at `at` (ending before `directoryEnd`) into `result`;
    // returns where the next one starts.
    std::size_t readEntry(std::size_t at, std::size_t directoryEnd, std::vector<UsdzPackage::Entry>& result) const {
        const char* record = "central directory entry";
        if (u32(at, record) != kDirectoryEntrySignature)
            fail("damaged zip archive (bad central directory entry signature)");
        std::size_t nameSize = u16(at + 28, record), extraSize = u16(at + 30, record),
                    commentSize = u16(at + 32, record);
        std::size_t next = at + kDirectoryEntrySize + nameSize + extraSize + commentSize;
        if (next > directoryEnd) fail("damaged zip archive (a central directory entry runs past the directory)");
        UsdzPackage::Entry entry;
        entry.name.assign(data_.substr(at + kDirectoryEntrySize, nameSize));
        const std::string named = "entry '" + entry.name + "'";
        if (entry.name.empty()) fail("damaged zip archive (an entry has no name)");
        if (u16(at + 8, record) & 1)
            entry.unreadable = "encrypted";
        else if (std::uint32_t method = u16(at + 10, record); method != 0)
            entry.unreadable = "compressed (zip method " + std::to_string(method) + ")";
        std::uint32_t storedSize = u32(at + 20, record), size = u32(at + 24, record), local = u32(at + 42, record);
        if (storedSize == 0xFFFFFFFF || size == 0xFFFFFFFF || local == 0xFFFFFFFF)
            fail(named + " needs zip64, which is not supported");
        if (entry.unreadable.empty() && storedSize != size)
            fail("damaged zip archive (" + named + " has a stored size unlike its size)");
        if (u32(local, "local file header") != kLocalHeaderSignature)
            fail("damaged zip archive (" + named + " has no local file header)");
        entry.offset =
            local + kLocalHeaderSize + u16(local + 26, "local file header") + u16(local + 28, "local file header");
        entry.size = storedSize;
        if (!fits(entry.offset, entry.size))
            fail("truncated zip archive (" + named + " runs past the end of the file)");
        result.push_back(std::move(entry));
        return next;
    }

    std::string_view data_;
    const std::string& path_;
};

constexpr std::size_t kMaxPackageNesting = 64;

// "a.usdz[b.usdz[c.png]]" as {"a.usdz", "b.usdz", "c.png"}; a path that is not package-relative
// as itself alone.
std::vector<std::string> packagePathParts(const std::string& path) {
    std::vector<std::string> parts;
    std::string rest = path;
    while (std::optional<PackagePath> split = splitPackagePath(rest)) {
        if (parts.size() == kMaxPackageNesting)
            throw FileError("'" + path + "': packages nested more than " + std::to_string(kMaxPackageNesting) +
                            " deep");
        parts.push_back(std::move(split->package));
        rest = std::move(split->entry);
    }
    parts.push_back(std::move(rest));
    return parts;
}

std::string joinPackagePathParts(const std::vector<std::string>& parts, std::size_t count) {
    std::string path = parts[0];
    for (std::size_t i = 1; i < count; ++i) path += "[" + parts[i];
    return path + std::string(count - 1, ']');
}

}  // namespace

UsdzPackage UsdzPackage::open(const std::string& path) {
    UsdzPackage package;
    package.path_ = path;
    if (std::optional<PackagePath> nested = splitInnermostPackagePath(path)) {
        UsdzPackage outer = open(nested->package);
        package.mapping_ = outer.mapping_;
        package.archive_ = outer.bytes(nested->entry);
    } else {
        package.mapping_ = mapFile(path);
        package.archive_ = *package.mapping_;
    }
    package.entries_ = ArchiveReader(package.archive_, path).entries();
    return package;
}

const UsdzPackage::Entry* UsdzPackage::find(std::string_view name) const {
    auto found = std::find_if(entries_.begin(), entries_.end(), [&](const Entry& e) { return e.name == name; });
    return found == entries_.end() ? nullptr : &*found;
}

std::string_view UsdzPackage::bytes(const Entry& entry) const {
    if (!entry.unreadable.empty())
        throw FileError("'" + path_ + "': entry '" + entry.name + "' is " + entry.unreadable +
                        "; USDZ entries must be stored uncompressed and unencrypted");
    return archive_.substr(entry.offset, entry.size);
}

std::string_view UsdzPackage::bytes(std::string_view name) const {
    const Entry* entry = find(name);
    if (!entry) throw FileError("'" + path_ + "' has no entry '" + std::string(name) + "'");
    return bytes(*entry);
}

std::optional<PackagePath> splitPackagePath(const std::string& path) {
    std::size_t open = path.find('[');
    if (open == std::string::npos || open == 0 || path.size() < open + 3 || path.back() != ']') return std::nullopt;
    return PackagePath{path.substr(0, open), path.substr(open + 1, path.size() - open - 2)};
}

std::optional<PackagePath> splitInnermostPackagePath(const std::string& path) {
    std::vector<std::string> parts = packagePathParts(path);
    if (parts.size() < 2) return std::nullopt;
    return PackagePath{joinPackagePathParts(parts, parts.size() - 1), parts.back()};
}

std::string packagePath(const std::string& package, const std::string& entry) {
    std::vector<std::string> parts = packagePathParts(package);
    parts.push_back(entry);
    return joinPackagePathParts(parts, parts.size());
}

bool isUsdzPath(const std::string& path) {
    std::optional<PackagePath> packaged = splitInnermostPackagePath(path);
    std::string extension = std::filesystem::path(packaged ? packaged->entry : path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return std::tolower(c); });
    return extension == ".usdz";
}

std::string packageRootLayer(const std::string& package) {
    try {
        UsdzPackage opened = UsdzPackage::open(package);
        return opened.entries().empty() ? "" : opened.entries().front().name;
    } catch (const FileError&) {
        return "";
    }
}

bool packagedEntryExists(const std::string& path) {
    std::optional<PackagePath> packaged = splitInnermostPackagePath(path);
    if (!packaged) return false;
    try {
        return UsdzPackage::open(packaged->package).find(packaged->entry) != nullptr;
    } catch (const FileError&) {
        return false;
    }
}

std::string packagedEntryProblem(const std::string& path) {
    if (!packagedEntryExists(path)) return "cannot find '" + path + "'";
    std::optional<PackagePath> packaged = splitInnermostPackagePath(path);
    try {
        UsdzPackage::open(packaged->package).bytes(packaged->entry);
        return "";
    } catch (const FileError& e) {
        return e.what();
    }
}

}  // namespace fluence::usd
