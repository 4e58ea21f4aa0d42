#include "scene/usda_names.h"

namespace fluence::usd::detail {

namespace {

bool isLetter(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_' ||
           static_cast<unsigned char>(c) >= 0x80;
}
bool isDigit(char c) { return c >= '0' && c <= '9'; }

bool isPathCharacter(char c) {
    return isLetter(c) || isDigit(c) ||
           std::string_view("/.:[]{}=|-").find(c) != std::string_view::npos;
}

}  // namespace

bool isIdentifier(std::string_view name) {
    if (name.empty() || !isLetter(name.front())) return false;
    for (char c : name) {
        if (!isLetter(c) && !isDigit(c)) return false;
    }
    return true;
}

bool isVariantName(std::string_view name) {
    if (!name.empty() && name.front() == '.') name.remove_prefix(1);
    if (name.empty()) return false;
    for (char c : name) {
        if (!isLetter(c) && !isDigit(c) && c != '|' && c != '-') return false;
    }
    return true;
}

bool isVariantSelection(std::string_view selection) {
    return selection.empty() || selection.front() == '`' || isVariantName(selection);
}

std::string pathProblem(std::string_view path, const PathRules& rules, int anchorDepth) {
    std::string quoted = std::string("<").append(path).append(">");
    if (path.empty()) return rules.allowEmpty ? "" : "empty path <>";
    for (char c : path) {
        if (!isPathCharacter(c))
            return "invalid character '" + std::string(1, c) + "' in path " + quoted;
    }
    if (!rules.allowVariantSelection && path.find('{') != std::string_view::npos) {
        return "variant selections are not allowed in path " + quoted;
    }
    // Walk the '/'-separated elements: leading ".." climb from the anchor; with primOnly no
    // element may name a property.
    bool absolute = path.front() == '/';
    int climbs = 0;
    bool leading = !absolute;
    std::size_t start = absolute ? 1 : 0;
    while (start <= path.size()) {
        std::size_t end = path.find('/', start);
        if (end == std::string_view::npos) end = path.size();
        std::string_view element = path.substr(start, end - start);
        if (element == "..") {
            if (leading) ++climbs;
        } else {
            leading = false;
            if (rules.primOnly && element != "." &&
                element.find_first_of(".[") != std::string_view::npos) {
                return quoted + " is not a prim path";
            }
        }
        start = end + 1;
    }
    if (climbs > anchorDepth) return "relative path " + quoted + " climbs above the root";
    return "";
}

}  // namespace fluence::usd::detail
