#include "scene/path_expression.h"

#include <fnmatch.h>

#include <cstdint>
#include <optional>
#include <utility>

namespace fluence::usd {

namespace {

// A predicate expression inside braces: a call, or not/and/or over operands.
struct Predicate {
    enum class Op { Call, Not, And, Or } op = Op::Call;
    PredicateCall call;
    std::vector<Predicate> operands;
};

struct Element {
    bool stretch = false;  // `//`: any number of levels
    std::string glob;      // fnmatch pattern of one prim name ("*" when only a predicate is written)
    std::optional<Predicate> predicate;
};

struct Pattern {
    std::vector<Element> elements;
    bool property = false;  // ends in a property element: matches no prim
};

bool isIdentifierChar(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
           static_cast<unsigned char>(c) >= 0x80;
}

std::vector<std::string> componentsOf(const std::string& path) {
    std::vector<std::string> parts;
    for (std::size_t start = 1; start < path.size();) {
        const std::size_t end = std::min(path.find('/', start), path.size());
        parts.push_back(path.substr(start, end - start));
        start = end + 1;
    }
    return parts;
}

}  // namespace

struct PathExpression::Node {
    // In order of precedence, highest first, for the operators.
    enum class Op { Complement, ImpliedUnion, Union, Intersection, Difference, Pattern, Reference, Nothing };
    Op op = Op::Nothing;
    Pattern pattern;
    Reference reference;
    std::unique_ptr<Node> left, right;
};

namespace {

using Node = PathExpression::Node;

class Parser {
public:
    Parser(std::string_view text, const std::string& anchor, std::vector<PathExpression::Reference>& references)
        : s_(text), anchor_(anchor), references_(references) {}

    std::unique_ptr<Node> parse() {
        auto root = expression();
        blanks();
        if (!end()) fail("unexpected '" + std::string(1, peek()) + "'");
        return root;
    }

private:
    // Parentheses, braces and `not`s nest at most this deep (deeper input is an error, not a stack
    // overflow).
    static constexpr int kMaxDepth = 200;
    // And an expression holds at most this many atoms, a pattern this many elements (the tree is
    // evaluated and freed recursively).
    static constexpr int kMaxAtoms = 10000;
    static constexpr std::size_t kMaxElements = 1000;

    std::string_view s_;
    std::size_t i_ = 0;
    int depth_ = 0;
    int atoms_ = 0;
    std::string anchor_;
    std::vector<PathExpression::Reference>& references_;

    [[noreturn]] void fail(const std::string& message, std::optional<std::size_t> at = {}) const {
        throw PathExpressionError("column " + std::to_string(at.value_or(i_) + 1) + ": " + message);
    }
    bool end() const { return i_ >= s_.size(); }
    char peek(std::size_t ahead = 0) const { return i_ + ahead < s_.size() ? s_[i_ + ahead] : '\0'; }
    bool blanks() {
        const std::size_t start = i_;
        while (!end() && (peek() == ' ' || peek() == '\t')) ++i_;
        return i_ > start;
    }
    // Counts one level of nesting for as long as it lives.
    struct Nested {
        Parser& parser;
        explicit Nested(Parser& p) : parser(p) {
            if (++parser.depth_ > kMaxDepth) parser.fail("nested more than " + std::to_string(kMaxDepth) + " deep");
        }
        ~Nested() { --parser.depth_; }
        Nested(const Nested&) = delete;
        Nested& operator=(const Nested&) = delete;
    };

    void expect(char c) {
        if (peek() != c) fail(std::string("expected '") + c + "'");
        ++i_;
    }

    // ---- Set expressions.
    std::unique_ptr<Node> expression() {
        const Nested nested(*this);
        std::vector<Node::Op> ops;
        std::vector<std::unique_ptr<Node>> operands;
        auto reduce = [&] {
            auto node = std::make_unique<Node>();
            node->op = ops.back();
            ops.pop_back();
            node->right = std::move(operands.back());
            operands.pop_back();
            if (node->op != Node::Op::Complement) {
                node->left = std::move(operands.back());
                operands.pop_back();
            }
            operands.push_back(std::move(node));
        };
        auto push = [&](Node::Op op) {
            while (!ops.empty() && ops.back() <= op) reduce();
            ops.push_back(op);
        };
        for (;;) {
            blanks();
            if (peek() == '~') {
                ++i_;
                push(Node::Op::Complement);
                blanks();
            }
            operands.push_back(atom());
            const bool spaced = blanks();
            if (end() || peek() == ')') break;
            if (peek() == '+' || peek() == '&' || peek() == '-') {
                push(peek() == '+' ? Node::Op::Union : peek() == '&' ? Node::Op::Intersection : Node::Op::Difference);
                ++i_;
            } else if (spaced) {
                push(Node::Op::ImpliedUnion);
            } else {
                fail("expected an operator (+, &, -, or a space) between path patterns");
            }
        }
        while (!ops.empty()) reduce();
        return std::move(operands.back());
    }

    std::unique_ptr<Node> atom() {
        if (end()) fail("expected a path pattern, a reference or '('");
        if (++atoms_ > kMaxAtoms) fail("more than " + std::to_string(kMaxAtoms) + " patterns and references");
        if (peek() == '(') {
            ++i_;
            auto inner = expression();
            blanks();
            expect(')');
            return inner;
        }
        auto node = std::make_unique<Node>();
        if (peek() == '%') {
            reference(*node);
        } else {
            node->op = Node::Op::Pattern;
            node->pattern = pattern();
        }
        return node;
    }

    // An absolute path from a relative one (`..` and `.` components resolved against the anchor).
    std::string anchored(const std::string& relative, std::size_t at) const {
        std::string path = anchor_;
        for (const std::string& part : componentsOf("/" + relative)) {
            if (part == "..") {
                if (path == "/") fail("'..' goes above the root", at);
                path = parentPrimPath(path);
            } else if (part != ".") {
                path = (path == "/" ? "" : path) + "/" + part;
            }
        }
        return path;
    }

    void reference(Node& node) {
        const std::size_t start = i_++;
        if (peek() == '_' && !isIdentifierChar(peek(1)) && peek(1) != ':') {
            ++i_;
            node.op = Node::Op::Nothing;  // %_, the weaker expression: none when read alone
            return;
        }
        std::string path;
        while (!end() && (isIdentifierChar(peek()) || peek() == '/' || peek() == '.')) path += s_[i_++];
        if (peek() != ':') fail("a reference is %<prim path>:<collection name>", start);
        ++i_;
        std::string name;
        while (!end() && isIdentifierChar(peek())) name += s_[i_++];
        if (name.empty()) fail("a reference needs a collection name after ':'");
        node.op = Node::Op::Reference;
        node.reference = {path.empty() ? anchor_ : path[0] == '/' ? path : anchored(path, start), name};
        references_.push_back(node.reference);
    }

    // ---- Path patterns.
    bool elementStart() const {
        const char c = peek();
        return isIdentifierChar(c) || c == '*' || c == '?' || c == '[' || c == '{';
    }

    Pattern pattern() {
        Pattern p;
        const std::size_t start = i_;
        if (peek() != '/') {  // relative: the anchor's path, `..` and `.` first
            std::string prefix;
            while (peek() == '.') {
                if (peek(1) == '.') {
                    prefix += "../";
                    i_ += 2;
                } else if (!isIdentifierChar(peek(1))) {
                    prefix += "./";
                    ++i_;
                } else {
                    break;
                }
                if (peek() == '/' && peek(1) != '/')
                    ++i_;
                else
                    break;
            }
            for (const std::string& part : componentsOf(anchored(prefix, start)))
                p.elements.push_back({false, part, {}});
            if (prefix.empty() && !elementStart()) fail("expected a path pattern");
        }
        for (bool needElement = false;;) {
            if (peek() == '/' && peek(1) == '/') {
                i_ += 2;
                p.elements.push_back({true, {}, {}});
                needElement = false;
            } else if (peek() == '/') {
                ++i_;
                needElement = true;
            } else if (elementStart()) {
                if (p.elements.size() >= kMaxElements)
                    fail("a pattern of more than " + std::to_string(kMaxElements) + " elements");
                p.elements.push_back(element());
                needElement = false;
                if (peek() == '.' && isIdentifierChar(peek(1))) {  // a property: no prim matches
                    ++i_;
                    while (!end() && (isIdentifierChar(peek()) || peek() == ':' || peek() == '*' || peek() == '?'))
                        ++i_;
                    p.property = true;
                    break;
                }
            } else {
                if (needElement && !p.elements.empty()) fail("expected a prim name pattern after '/'");
                break;
            }
        }
        return p;
    }

    Element element() {
        Element e;
        while (!end() && (isIdentifierChar(peek()) || peek() == '*' || peek() == '?' || peek() == '[')) {
            if (peek() == '[') {
                const std::size_t open = i_;
                const std::size_t close = s_.find(']', i_ + 1);
                if (close == std::string_view::npos) fail("'[' without ']'", open);
                e.glob += s_.substr(i_, close + 1 - i_);
                i_ = close + 1;
            } else {
                e.glob += s_[i_++];
            }
        }
        if (e.glob.empty()) e.glob = "*";
        if (peek() == '{') {
            ++i_;
            blanks();
            e.predicate = orPredicate();
            blanks();
            expect('}');
        }
        return e;
    }

    // ---- Predicate expressions (inside braces).
    bool keyword(std::string_view word) const {
        return s_.substr(i_).starts_with(word) && !isIdentifierChar(peek(word.size()));
    }

    Predicate orPredicate() {
        const Nested nested(*this);
        Predicate first = andPredicate();
        if (!keyword("or")) return first;
        Predicate p{Predicate::Op::Or, {}, {std::move(first)}};
        while (keyword("or")) {
            i_ += 2;
            blanks();
            p.operands.push_back(andPredicate());
        }
        return p;
    }

    Predicate andPredicate() {
        Predicate p{Predicate::Op::And, {}, {}};
        for (;;) {
            p.operands.push_back(unaryPredicate());
            blanks();
            if (keyword("and")) {
                i_ += 3;
                blanks();
            } else if (end() || peek() == '}' || peek() == ')' || keyword("or")) {
                break;
            }  // else an implied and
        }
        return p.operands.size() == 1 ? std::move(p.operands[0]) : std::move(p);
    }

    Predicate unaryPredicate() {
        const Nested nested(*this);
        if (keyword("not")) {
            i_ += 3;
            blanks();
            return Predicate{Predicate::Op::Not, {}, {unaryPredicate()}};
        }
        if (peek() == '(') {
            ++i_;
            blanks();
            Predicate inner = orPredicate();
            blanks();
            expect(')');
            return inner;
        }
        const std::size_t start = i_;
        Predicate p;
        while (!end() && isIdentifierChar(peek())) p.call.name += s_[i_++];
        if (p.call.name.empty()) fail("expected a predicate function");
        if (peek() == ':') {
            ++i_;
            do {
                if (peek() == ',') ++i_;
                p.call.args.push_back(argument(false));
            } while (peek() == ',');
        } else if (peek() == '(') {
            ++i_;
            blanks();
            while (peek() != ')') {
                std::string value = argument(true);
                blanks();
                if (peek() == '=') {
                    ++i_;
                    blanks();
                    p.call.keywords[value] = argument(true);
                    blanks();
                } else {
                    p.call.args.push_back(std::move(value));
                }
                if (peek() == ',') {
                    ++i_;
                    blanks();
                } else if (peek() != ')') {
                    fail("expected ',' or ')' in the arguments of '" + p.call.name + "'");
                }
            }
            ++i_;
        }
        try {
            checkPredicate(p.call);
        } catch (const PredicateError& e) {
            fail(e.what(), start);
        }
        return p;
    }

    // One argument value: a double-quoted string, or a run of characters up to a separator.
    std::string argument(bool inParentheses) {
        std::string value;
        if (peek() == '"') {
            const std::size_t close = s_.find('"', i_ + 1);
            if (close == std::string_view::npos) fail("unterminated string");
            value = s_.substr(i_ + 1, close - i_ - 1);
            i_ = close + 1;
            return value;
        }
        const std::string_view stops = inParentheses ? ",)= \t" : ",}) \t";
        while (!end() && stops.find(peek()) == std::string_view::npos) value += s_[i_++];
        if (value.empty()) fail("expected an argument");
        return value;
    }
};

bool satisfies(const Predicate& p, const Stage& stage, const std::string& path) {
    switch (p.op) {
        case Predicate::Op::Call: return evaluatePredicate(p.call, stage, path);
        case Predicate::Op::Not: return !satisfies(p.operands[0], stage, path);
        case Predicate::Op::And:
            for (const Predicate& o : p.operands)
                if (!satisfies(o, stage, path)) return false;
            return true;
        case Predicate::Op::Or:
            for (const Predicate& o : p.operands)
                if (satisfies(o, stage, path)) return true;
            return false;
    }
    return false;
}

// Whether a pattern matches a path: elements against components, each (element, component)
// pair decided once (stretches would otherwise backtrack exponentially).
class PatternMatch {
public:
    PatternMatch(const Pattern& p, const std::vector<std::string>& parts, const std::vector<std::string>& prefixes,
                 const Stage& stage)
        : p_(p),
          parts_(parts),
          prefixes_(prefixes),
          stage_(stage),
          memo_((p.elements.size() + 1) * (parts.size() + 1), Unknown) {}

    bool operator()() { return from(0, 0); }

private:
    enum : std::int8_t { Unknown = -1, No = 0, Yes = 1 };
    const Pattern& p_;
    const std::vector<std::string>& parts_;
    const std::vector<std::string>& prefixes_;  // prefixes_[i + 1]: the path of component i
    const Stage& stage_;
    std::vector<std::int8_t> memo_;

    // Whether elements [j, end) match components [i, end).
    bool from(std::size_t j, std::size_t i) {
        std::int8_t& known = memo_[j * (parts_.size() + 1) + i];
        if (known == Unknown) known = decide(j, i) ? Yes : No;
        return known == Yes;
    }
    bool decide(std::size_t j, std::size_t i) {
        if (j == p_.elements.size()) return i == parts_.size();
        const Element& e = p_.elements[j];
        if (e.stretch) return from(j + 1, i) || (i < parts_.size() && from(j, i + 1));
        if (i == parts_.size() || fnmatch(e.glob.c_str(), parts_[i].c_str(), 0) != 0) return false;
        if (e.predicate && !satisfies(*e.predicate, stage_, prefixes_[i + 1])) return false;
        return from(j + 1, i + 1);
    }
};

bool evaluate(const Node& n, const std::string& path, const std::vector<std::string>& parts,
              const std::vector<std::string>& prefixes, const Stage& stage,
              const PathExpression::ReferenceMembership& membership) {
    auto sub = [&](const std::unique_ptr<Node>& child) {
        return evaluate(*child, path, parts, prefixes, stage, membership);
    };
    switch (n.op) {
        case Node::Op::Pattern: return !n.pattern.property && PatternMatch(n.pattern, parts, prefixes, stage)();
        case Node::Op::Reference: return membership(n.reference, path);
        case Node::Op::Nothing: return false;
        case Node::Op::Complement: return !sub(n.right);
        case Node::Op::ImpliedUnion:
        case Node::Op::Union: return sub(n.left) || sub(n.right);
        case Node::Op::Intersection: return sub(n.left) && sub(n.right);
        case Node::Op::Difference: return sub(n.left) && !sub(n.right);
    }
    return false;
}

}  // namespace

PathExpression::PathExpression(std::string_view text, const std::string& anchor) {
    root_ = Parser(text, anchor, references_).parse();  // in the body: the parser fills references_
}
PathExpression::~PathExpression() = default;
PathExpression::PathExpression(PathExpression&&) noexcept = default;
PathExpression& PathExpression::operator=(PathExpression&&) noexcept = default;

bool PathExpression::matches(const std::string& path, const Stage& stage, const ReferenceMembership& membership) const {
    const std::vector<std::string> parts = componentsOf(path);
    std::vector<std::string> prefixes{"/"};
    for (const std::string& part : parts)
        prefixes.push_back((prefixes.size() == 1 ? "" : prefixes.back()) + "/" + part);
    return evaluate(*root_, path, parts, prefixes, stage, membership);
}

}  // namespace fluence::usd
