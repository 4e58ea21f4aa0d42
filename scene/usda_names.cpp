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
    return c < 0x80 && std::string_view("/.:[]{}=|-").find(static_cast<char>(c)) != std::string_view::npos;
}

// SdfPath's syntax (pathParser.h): '/' [primElts [propElts]] | '..' ('/' '..')* ['/' pathElts]
// | pathElts | '.', where pathElts is primElts [propElts] or propElts, primElts is prim names
// joined by '/' or variant selections (and may end with one), and propElts is '.' then
// identifiers joined by ':'. Target and mapper paths ('[' ... ']') are not checked further, nor
// blanks inside variant selections (the character check refuses them first).
class PathSyntax {
public:
    explicit PathSyntax(std::string_view path) : path_(path) {}

    bool valid() {
        if (path_ == "." || path_.find('[') != std::string_view::npos) return true;
        if (eat('/')) return atEnd() || (primElements() && optionalProperty());
        if (path_.substr(0, 2) == "..") {
            pos_ = 2;
            while (path_.substr(pos_, 3) == "/..") pos_ += 3;
            if (atEnd()) return true;
            if (!eat('/')) return false;
        }
        std::size_t start = pos_;
        if (primElements()) return optionalProperty();
        return pos_ == start && property() && atEnd();
    }

private:
    bool atEnd() const { return pos_ == path_.size(); }
    bool eat(char c) {
        if (atEnd() || path_[pos_] != c) return false;
        ++pos_;
        return true;
    }
    // Characters while accept(codePoint, first) holds; false when there were none.
    template <class Accept>
    bool run(Accept&& accept) {
        std::size_t start = pos_;
        while (!atEnd()) {
            Utf8Char c = decodeUtf8(path_, pos_);
            if (!c.length || !accept(c.codePoint, pos_ == start)) break;
            pos_ += c.length;
        }
        return pos_ > start;
    }
    bool identifier() {
        return run([](char32_t c, bool first) { return first ? c == '_' || isXidStart(c) : isXidContinue(c); });
    }
    bool variantSelection() {
        if (!eat('{')) return false;
        if (!run([](char32_t c, bool first) {
                return first ? c == '_' || isXidStart(c) : isXidContinue(c) || c == '-';
            }))
            return false;
        if (!eat('=')) return false;
        eat('.');
        run([](char32_t c, bool) { return isXidContinue(c) || c == '|' || c == '-'; });
        return eat('}');
    }
    bool primElements() {
        if (!identifier()) return false;
        while (!atEnd() && (path_[pos_] == '/' || path_[pos_] == '{')) {
            if (eat('/')) {
                if (!identifier()) return false;
            } else {
                while (!atEnd() && path_[pos_] == '{') {
                    if (!variantSelection()) return false;
                }
                if (!atEnd() && path_[pos_] != '.' && !identifier()) return false;
            }
        }
        return true;
    }
    bool property() {
        if (!eat('.') || !identifier()) return false;
        while (eat(':')) {
            if (!identifier()) return false;
        }
        return true;
    }
    bool optionalProperty() { return (atEnd() || property()) && atEnd(); }

    std::string_view path_;
    std::size_t pos_ = 0;
};

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
    if (!PathSyntax(path).valid()) return quoted + " is not a valid path";
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
            if (rules.primOnly && element != "." && element.find_first_of(".[") != std::string_view::npos) {
                return quoted + " is not a prim path";
            }
        }
        start = end + 1;
    }
    if (climbs > anchorDepth) return "relative path " + quoted + " climbs above the root";
    return "";
}

}  // namespace fluence::usd::detail
