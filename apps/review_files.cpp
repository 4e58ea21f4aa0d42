#include "apps/review_files.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>
#include <regex>
#include <set>

namespace fs = std::filesystem;

namespace fluence::app {

namespace {

bool isExr(const fs::path& p) {
    std::string ext = p.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    return ext == ".exr";
}

std::string escapeRegex(const std::string& text) {
    static const std::regex special(R"([.^$|()\[\]{}*+?\\])");
    return std::regex_replace(text, special, R"(\$&)");
}

// A frame pattern in a file name: the text before and after it and its digit count (0: any).
struct FramePattern {
    std::string before, after;
    int width = 0;
};

std::optional<FramePattern> framePattern(const std::string& fileName) {
    std::smatch m;
    static const std::regex houdini(R"(^(.*)\$F(\d?)(.*)$)");
    static const std::regex hashes(R"(^([^#]*)(#+)([^#]*)$)");
    if (std::regex_match(fileName, m, houdini)) return FramePattern{m[1], m[3], m[2].length() ? std::stoi(m[2]) : 0};
    if (std::regex_match(fileName, m, hashes)) return FramePattern{m[1], m[3], int(m[2].length())};
    return std::nullopt;
}

std::vector<ReviewFile> expandSequence(const fs::path& path, const FramePattern& pattern) {
    const fs::path folder = path.has_parent_path() ? path.parent_path() : fs::path(".");
    const std::string digits = pattern.width ? "(\\d{" + std::to_string(pattern.width) + "})" : "(\\d+)";
    const std::regex match("^" + escapeRegex(pattern.before) + digits + escapeRegex(pattern.after) + "$");
    const std::string sequence =
        (path.parent_path() / (pattern.before + std::string(std::max(pattern.width, 1), '#') + pattern.after))
            .generic_string();
    std::vector<ReviewFile> frames;
    std::error_code ec;
    for (const fs::directory_entry& entry : fs::directory_iterator(folder, ec)) {
        const std::string fileName = entry.path().filename().string();
        std::smatch m;
        if (!entry.is_regular_file() || !std::regex_match(fileName, m, match)) continue;
        frames.push_back({(path.parent_path() / fileName).generic_string(), fs::canonical(entry.path()).string(),
                          sequence, std::stoi(m[1])});
    }
    if (frames.empty()) throw ReviewInputError(path.string() + ": no file matches this frame sequence");
    std::sort(frames.begin(), frames.end(), [](const ReviewFile& a, const ReviewFile& b) { return a.frame < b.frame; });
    return frames;
}

std::vector<ReviewFile> expandFolder(const fs::path& folder) {
    const fs::path root = fs::canonical(folder);
    const std::string rootName = root.filename().string();
    std::vector<ReviewFile> files;
    for (const fs::directory_entry& entry : fs::recursive_directory_iterator(root)) {
        if (!entry.is_regular_file() || !isExr(entry.path())) continue;
        const fs::path real = fs::canonical(entry.path());
        const fs::path inside = real.lexically_relative(root);
        if (inside.empty() || *inside.begin() == "..") continue;  // a symlink out of the folder
        files.push_back(
            {(fs::path(rootName) / entry.path().lexically_relative(root)).generic_string(), real.string(), "", 0});
    }
    std::sort(files.begin(), files.end(), [](const ReviewFile& a, const ReviewFile& b) { return a.name < b.name; });
    return files;
}

// Files named <prefix><digits>.exr sharing the prefix and the digit count become one sequence.
void groupSequences(std::vector<ReviewFile>& files) {
    static const std::regex numbered(R"(^(.*?)(\d+)(\.[eE][xX][rR])$)");
    std::map<std::string, std::vector<std::size_t>> groups;
    for (std::size_t i = 0; i < files.size(); ++i) {
        std::smatch m;
        if (!files[i].sequence.empty() || !std::regex_match(files[i].name, m, numbered)) continue;
        groups[m.str(1) + std::string(m[2].length(), '#') + m.str(3)].push_back(i);
    }
    for (const auto& [sequence, members] : groups) {
        if (members.size() < 2) continue;
        for (std::size_t i : members) {
            std::smatch m;
            std::regex_match(files[i].name, m, numbered);
            files[i].sequence = sequence;
            files[i].frame = std::stoi(m[2]);
        }
    }
}

}  // namespace

std::vector<ReviewFile> expandReviewPaths(const std::vector<std::string>& paths) {
    std::vector<ReviewFile> files;
    for (const std::string& text : paths) {
        const fs::path path(text);
        std::vector<ReviewFile> found;
        std::error_code ec;
        if (auto pattern = framePattern(path.filename().string()); pattern && !fs::exists(path, ec)) {
            found = expandSequence(path, *pattern);
        } else if (fs::is_directory(path, ec)) {
            found = expandFolder(path);
            if (found.empty()) throw ReviewInputError(text + ": the folder holds no .exr file");
        } else if (fs::is_regular_file(path, ec)) {
            found.push_back({path.filename().string(), fs::canonical(path).string(), "", 0});
        } else {
            throw ReviewInputError(text + ": no such file or folder");
        }
        files.insert(files.end(), found.begin(), found.end());
    }
    std::set<std::string> names;
    for (const ReviewFile& f : files)
        if (!names.insert(f.name).second) throw ReviewInputError("two inputs are both named '" + f.name + "'");
    groupSequences(files);
    return files;
}

bool isUnsafeReviewName(const std::string& name) {
    if (name.empty() || name.front() == '/' || name.find('\\') != std::string::npos ||
        name.find('\0') != std::string::npos || name.find(':') != std::string::npos)
        return true;
    for (const fs::path& part : fs::path(name))
        if (part == "..") return true;
    return false;
}

std::optional<ReviewFile> findReviewFile(const std::vector<ReviewFile>& files, const std::string& name) {
    if (isUnsafeReviewName(name)) return std::nullopt;
    for (const ReviewFile& f : files)
        if (f.name == name) return f;
    return std::nullopt;
}

}  // namespace fluence::app
