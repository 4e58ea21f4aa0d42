#include "scene/namespace_remap.h"

#include <algorithm>

namespace fluence::usd::detail {

namespace {

std::string parentPrimPath(const std::string& path) {
    std::size_t slash = path.rfind('/');
    return slash == 0 || slash == std::string::npos ? "/" : path.substr(0, slash);
}

}  // namespace

std::string stripVariantSelections(std::string_view path) {
    std::string out;
    out.reserve(path.size());
    bool afterSelection = false;
    for (std::size_t i = 0; i < path.size(); ++i) {
        if (path[i] == '{') {
            std::size_t close = path.find('}', i);
            if (close == std::string_view::npos) break;
            i = close;
            afterSelection = true;
            continue;
        }
        // "/A{v=x}B": the selection stood where the separator goes.
        if (afterSelection && path[i] != '.' && path[i] != '/') out += '/';
        afterSelection = false;
        out += path[i];
    }
    return out;
}

std::string childPrimPath(std::string_view parent, std::string_view name) {
    std::string out(parent);
    if (out.empty() || (out.back() != '/' && out.back() != '}')) out += '/';
    out += name;
    return out;
}

bool hasPathPrefix(std::string_view path, std::string_view prefix) {
    if (prefix == "/") return !path.empty() && path.front() == '/';
    if (path.substr(0, prefix.size()) != prefix) return false;
    if (path.size() == prefix.size()) return true;
    char next = path[prefix.size()];
    return next == '/' || next == '.' || next == '{';
}

std::string absolutePath(std::string_view anchor, std::string_view path) {
    if (!path.empty() && path.front() == '/') return std::string(path);
    std::string base(anchor.empty() ? "/" : anchor);
    std::string_view rest = path;
    while (true) {
        if (rest.substr(0, 3) == "../") {
            base = parentPrimPath(base);
            rest.remove_prefix(3);
        } else if (rest == "..") {
            return parentPrimPath(base);
        } else if (rest.substr(0, 2) == "./") {
            rest.remove_prefix(2);
        } else if (rest == ".") {
            return base;
        } else {
            break;
        }
    }
    if (rest.empty()) return base;
    if (rest.front() == '.') return base + std::string(rest);
    return (base == "/" ? "" : base) + "/" + std::string(rest);
}

int pathDepth(std::string_view path) {
    std::string prim = stripVariantSelections(path);
    prim = prim.substr(0, prim.find('.'));
    int depth = 0;
    for (std::size_t i = 0; i < prim.size(); ++i)
        if (prim[i] == '/' && i + 1 < prim.size()) ++depth;
    return depth;
}

std::vector<std::string> primNames(std::string_view path) {
    std::vector<std::string> names;
    for (std::size_t start = 1; start < path.size();) {
        std::size_t slash = std::min(path.find('/', start), path.size());
        names.emplace_back(path.substr(start, slash - start));
        start = slash + 1;
    }
    return names;
}

MapFunction::MapFunction(std::string source, std::string target)
    : source_(std::move(source)), target_(std::move(target)) {}

std::string MapFunction::map(std::string_view path) const {
    if (!hasPathPrefix(path, source_)) return std::string(path);
    return target_ + std::string(path.substr(source_.size()));
}

}  // namespace fluence::usd::detail
