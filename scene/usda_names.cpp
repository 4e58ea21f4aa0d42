#include "scene/usda_names.h"

#include "scene/unicode_xid.h"
#include "scene/utf8.h"

namespace fluence::usd::detail {

namespace {

// Calls visit(codePoint, offset) for each character of `text` while it returns an empty string;
// returns the first non-empty answer, or what is malformed.
template <class Visit>
std::string firstProblem(std::string_view text, Visit&& visit) {
    for (std::size_t pos = 0; pos < text.size();) {
        Utf8Char c = decodeUtf8(text, pos);
        if (!c.length) return describeMalformedUtf8(text, pos);
        if (std::string problem = visit(c.codePoint, pos); !problem.empty()) return problem;
        pos += c.length;
    }
    return "";
}

bool isPathSyntax(char32_t c) {
    return c < 0x80 && std::string_view("/.:[]{}=|-").find(static_cast<char>(c)) !=
                           std::string_view::npos;
}

}  // namespace

std::string identifierProblem(std::string_view name) {
    if (name.empty()) return "a name cannot be empty";
    return firstProblem(name, [](char32_t c, std::size_t offset) -> std::string {
        if (offset == 0 && c != '_' && !isXidStart(c)) {
            return describeCodePoint(c) + " cannot start a name";
        }
        if (!isXidContinue(c)) return describeCodePoint(c) + " cannot be part of a name";
        return "";
    });
}

bool isVariantName(std::string_view name) {
    if (!name.empty() && name.front() == '.') name.remove_prefix(1);
    if (name.empty()) return false;
    auto problem = [](char32_t c, std::size_t) -> std::string {
        return isXidContinue(c) || c == '|' || c == '-' ? "" : describeCodePoint(c);
    };
    return firstProblem(name, problem).empty();
}

bool isVariantSelection(std::string_view selection) {
    return selection.empty() || selection.front() == '`' || isVariantName(selection);
}

std::string pathProblem(std::string_view path, const PathRules& rules, int anchorDepth) {
    std::string quoted = std::string("<").append(path).append(">");
    if (path.empty()) return rules.allowEmpty ? "" : "empty path <>";
    std::string characters = firstProblem(path, [](char32_t c, std::size_t) -> std::string {
        if (isPathSyntax(c) || isXidContinue(c)) return "";
        if (c >= 0x20 && c < 0x7f) {
            return "invalid character '" + std::string(1, static_cast<char>(c)) + "'";
        }
        return "invalid character " + describeCodePoint(c);
    });
    if (!characters.empty()) return characters + " in path " + quoted;
    if (!rules.allowVariantSelection && path.find('{') != std::string_view::npos) {
        return "variant selections are not allowed in path " + quoted;
    }
    // Walk the '/'-separated elements: leading ".." climb from the anchor; with primOnly no
    // element may name a property.
    bool absolute = path.front() == '/';
    if (rules.absoluteOnly && !absolute) return quoted + " must be an absolute path";
    if (rules.primOnly && path == "/") return quoted + " is not a prim path";
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
