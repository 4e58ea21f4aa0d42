// Light path expressions: tables of expressions against paths, syntax errors with their columns,
// a randomised cross-check of the automaton against a plain reference matcher over the parse tree
// of random expressions, and partitions of C.*L that must accept every path exactly once.
#include "integrators/light_path_expression.h"

#include <gtest/gtest.h>

#include <functional>
#include <memory>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace fluence::integrators {
namespace {

constexpr std::string_view kTypeLetters = "CRTVLOB";
constexpr std::string_view kScatteringLetters = "-DGSs";

// An event owning its label, so random paths can be kept in vectors.
struct Event {
    EventType type;
    Scattering scattering = Scattering::None;
    std::string label = {};
};
using Path = std::vector<Event>;

// "C RD TS'subsurface' L'key'": per event a type letter, an optional scattering letter and an
// optional quoted label.
Path parsePath(const std::string& text) {
    Path path;
    std::istringstream in(text);
    for (std::string token; in >> token;) {
        Event event{static_cast<EventType>(kTypeLetters.find(token[0]))};
        std::size_t at = 1;
        if (at < token.size() && token[at] != '\'')
            event.scattering = static_cast<Scattering>(kScatteringLetters.find(token[at++]));
        if (at < token.size()) event.label = token.substr(at + 1, token.size() - at - 2);
        path.push_back(event);
    }
    return path;
}

bool accepts(const LightPathExpression& expression, const Path& path) {
    int state = expression.start();
    for (const Event& event : path) state = expression.next(state, {event.type, event.scattering, event.label});
    return expression.accepts(state);
}

struct MatchCase {
    const char* expression;
    const char* path;
    bool matches;
};

const MatchCase kMatchCases[] = {
    {"C<RD>L", "C RD L", true},
    {"C<RD>L", "C RG L", false},
    {"C<RD>L", "C TD L", false},
    {"C<RD>L", "C RD RD L", false},
    {"C<RD>L", "C RD", false},  // anchored at the end
    {"C<RD>L", "RD L", false},  // and at the start
    {"C <R D> L", "C RD L", true},
    {"C<R>L", "C RS L", true},  // omitted positions are wildcards
    {"C<>L", "C TG L", true},
    {"C<RS>.*L", "C RS L", true},
    {"C<RS>.*L", "C RS TD RG VD L", true},
    {"C<RS>.*L", "C RD RS L", false},
    {"CD+L", "C RD TD VD L", true},
    {"CD+L", "C L", false},
    {"CD+L", "C RD RG L", false},
    {"C<TS>.*L", "C TS TS RD L", true},
    {"C<TS>.*L", "C RS L", false},
    {"C.*L", "C L", true},
    {"C.*L", "C RD VD TS O L", true},
    {"C.*L", "C RD", false},
    {"C.*L", "C RD O", false},
    {"C[^S]*L", "C RD RG Ts L", true},
    {"C[^S]*L", "C RD RS L", false},
    {"C<V>+L", "C VD VD L", true},
    {"C<V>+L", "C VD RD L", false},
    {"C<V>+L", "C L", false},
    {"C<.D'subsurface'>*L", "C RD'subsurface' TD'subsurface' L", true},
    {"C<.D'subsurface'>*L", "C L", true},
    {"C<.D'subsurface'>*L", "C RD L", false},
    {"C<.D'subsurface'>*L", "C RG'subsurface' L", false},
    {"C.*<L'key'>", "C RD L'key'", true},
    {"C.*<L'key'>", "C L'key'", true},
    {"C.*<L'key'>", "C RD L'fill'", false},
    {"C.*<L'key'>", "C RD L", false},
    {"C.*<L'key'>", "C RD O'key'", false},
    {"C.*<'key'>", "C RD O'key'", true},  // a label may come early: <'key'> is <..'key'>
    {"C<R['key']>L", "C RS'key' L", true},
    {"C<R[^'key']>L", "C RS'key' L", false},
    {"C.*'key'", "C RD O'key'", true},
    {"C<..[^'key']>", "C L'fill'", true},
    {"C<..[^'key']>", "C L", true},
    {"C<..[^'key']>", "C L'key'", false},
    {"C<..['key' 'fill']>", "C L'fill'", true},
    {"C<..['key' 'fill']>", "C L'rim'", false},
    {"C(D|G){2}L", "C RD TG L", true},
    {"C(D|G){2}L", "C RD L", false},
    {"C(D|G){2}L", "C RD RG RD L", false},
    {"C(D|G){2}L", "C RD RS L", false},
    {"CD{1,2}L", "C L", false},
    {"CD{1,2}L", "C RD RD L", true},
    {"CD{1,2}L", "C RD RD RD L", false},
    {"CD{2,}L", "C RD L", false},
    {"CD{2,}L", "C RD RD RD RD L", true},
    {"C.{0}L", "C L", true},
    {"C<R[DG]>L", "C RG L", true},
    {"C<R[DG]>L", "C RS L", false},
    {"C<[RT]S>L", "C TS L", true},
    {"C<[RT]S>L", "C VS L", false},
    {"C<R[^D]>L", "C R L", true},
    {"C<R[^D]>L", "C RD L", false},
    {"C<[^RT]>L", "C VD L", true},
    {"C<[^RT]>L", "C TD L", false},
    {"C<.s>L", "C Ts L", true},
    {"C<.s>L", "C TS L", false},  // straight and singular differ
    {"C[DG]L", "C TG L", true},
    {"C[DG]L", "C TS L", false},
    {"C[R'subsurface']L", "C TD'subsurface' L", true},
    {"C[R'subsurface']L", "C RS L", true},
    {"C[R'subsurface']L", "C TD L", false},
    {"C[^R'subsurface']L", "C TD L", true},
    {"C[^R'subsurface']L", "C TD'subsurface' L", false},
    {"CRDL", "C RS TD L", true},  // outside brackets R then D are two events
    {"CRDL", "C RD L", false},
    {"C?L", "L", true},
    {"C?L", "C L", true},
    {"CB", "C B", true},
    {"C.*O", "C RD O", true},
    {"C.*[LO]", "C RD O", true},
    {"C.*[LO]", "C RD B", false},
    {"C<RD>L|C<TS>L", "C TS L", true},
    {"C<RD>L|C<TS>L", "C RS L", false},
    {"(C)(<RD>)(L)", "C RD L", true},
    {"C(<RD>|<TS>+)L", "C TS TS L", true},
    {"C(<RD>|<TS>+)L", "C RD RD L", false},
    {"C(D?G)*L", "C RG RD TG L", true},
    {"C(D?G)*L", "C RD L", false},
    {"C.*", "C", true},
};

TEST(LightPathExpression, MatchesTheTable) {
    for (const MatchCase& c : kMatchCases) {
        const LightPathExpression expression(c.expression);
        EXPECT_EQ(accepts(expression, parsePath(c.path)), c.matches) << c.expression << " on " << c.path;
    }
}

TEST(LightPathExpression, DeadStateIsTerminal) {
    const LightPathExpression expression("C<RD>L");
    EXPECT_EQ(expression.text(), "C<RD>L");
    const int afterCamera = expression.next(expression.start(), {EventType::Camera});
    ASSERT_NE(afterCamera, LightPathExpression::kDead);
    EXPECT_EQ(expression.next(afterCamera, {EventType::Reflection, Scattering::Singular}), LightPathExpression::kDead);
    EXPECT_EQ(expression.next(LightPathExpression::kDead, {EventType::Light}), LightPathExpression::kDead);
    EXPECT_FALSE(expression.accepts(LightPathExpression::kDead));
    // A state from which the path can still be extended to a match is not dead.
    EXPECT_NE(expression.next(afterCamera, {EventType::Reflection, Scattering::Diffuse}), LightPathExpression::kDead);

    const LightPathExpression nothing("C[^CRTVLOB]");
    EXPECT_EQ(nothing.start(), LightPathExpression::kDead);
    EXPECT_EQ(nothing.stateCount(), 0);
}

TEST(LightPathExpression, AutomatonIsMinimal) {
    EXPECT_EQ(LightPathExpression("C.*L").stateCount(), 3);
    EXPECT_EQ(LightPathExpression("C<RD>L").stateCount(), 4);
    EXPECT_EQ(LightPathExpression("C(D|D)L").stateCount(), LightPathExpression("CDL").stateCount());
    EXPECT_EQ(LightPathExpression("C(D|G)*L").stateCount(), LightPathExpression("C[DG]*L").stateCount());
}

struct ErrorCase {
    const char* expression;
    const char* what;
};

const ErrorCase kErrorCases[] = {
    {"", "column 1: empty expression"},
    {"   ", "column 1: empty expression"},
    {"C(RD", "column 2: unclosed '('"},
    {"CRD)", "column 4: unmatched ')'"},
    {"C<RD", "column 2: unclosed '<'"},
    {"(C<RD)L", "column 3: unclosed '<'"},
    {"CRD>", "column 4: unmatched '>'"},
    {"C[DG", "column 2: unclosed '['"},
    {"CDG]", "column 4: unmatched ']'"},
    {"C'key", "column 2: unclosed quote"},
    {"C<R''>L", "column 4: empty label"},
    {"C<[R'key']>L", "column 5: a label belongs in the third position"},
    {"C<X>L", "column 3: unknown letter 'X'"},
    {"CXL", "column 2: unknown letter 'X'"},
    {"C#", "column 2: unexpected character '#'"},
    {"C<DR>L", "column 3: 'D' is a scattering, not an event type"},
    {"C<RR>L", "column 4: 'R' is an event type, not a scattering"},
    {"C<R[DT]>L", "column 6: 'T' is an event type, not a scattering"},
    {"C<RDS>L", "column 5: expected a quoted label in the third position, not 'S'"},
    {"C<RD'a'.>L", "column 8: an event ends after its label (positions: type, scattering, label)"},
    {"C<L'a'D>", "column 7: an event ends after its label (positions: type, scattering, label)"},
    {"*C", "column 1: '*' has nothing to repeat"},
    {"C|*L", "column 3: '*' has nothing to repeat"},
    {"(+C)", "column 2: '+' has nothing to repeat"},
    {"{2}C", "column 1: '{' has nothing to repeat"},
    {"C{3,2}", "column 2: reversed repetition bounds (3 > 2)"},
    {"C{}", "column 3: expected a number after '{'"},
    {"C{,2}", "column 3: expected a number after '{'"},
    {"C{2", "column 2: unclosed '{'"},
    {"C{2,x}", "column 5: expected a number or '}' after ','"},
    {"C{1001}", "column 3: repetition bound above 1000"},
    {"C}", "column 2: unmatched '}'"},
    {"C||L", "column 3: nothing to match before '|'"},
    {"C|", "column 3: nothing to match at the end"},
    {"()", "column 2: nothing to match before ')'"},
    {"C[^]L", "column 2: empty set"},
    {"C[D.]L", "column 4: '.' in a set (a set lists letters and labels)"},
    {"C.*R.{12}L", "column 1: expression too complex (its automaton would need more than 4096 states)"},
    {"((C{1000}){1000}){1000}", "column 1: expression too complex (its repetitions expand to more than 65536 steps)"},
};

TEST(LightPathExpression, ReportsSyntaxErrorsWithTheirColumn) {
    const std::string deepGroups = std::string(101, '(') + "C" + std::string(101, ')');
    const std::string deepRepetitions = "C" + std::string(101, '*');
    std::vector<ErrorCase> cases(std::begin(kErrorCases), std::end(kErrorCases));
    cases.push_back({deepGroups.c_str(), "column 101: groups and repetitions nested more than 100 deep"});
    cases.push_back({deepRepetitions.c_str(), "column 102: groups and repetitions nested more than 100 deep"});
    for (const ErrorCase& c : cases) {
        try {
            const LightPathExpression expression(c.expression);
            ADD_FAILURE() << "'" << c.expression << "' parsed";
        } catch (const LpeSyntaxError& error) {
            EXPECT_EQ(std::string(error.what()), c.what) << c.expression;
        }
    }
}

// ---- The reference: random expressions built as trees, printed, and matched by walking the tree.

struct ReferenceNode {
    enum class Kind { Event, Sequence, Alternation, Repetition } kind;
    std::string text = {};                           // Event: its text
    std::function<bool(const Event&)> matches = {};  // Event
    std::vector<ReferenceNode> children = {};
    int min = 0, max = 0;  // Repetition, max -1 for none

    // The positions where a match of this node starting at `from` can end.
    std::set<std::size_t> ends(const Path& path, std::size_t from) const {
        switch (kind) {
            case Kind::Event:
                if (from < path.size() && matches(path[from])) return {from + 1};
                return {};
            case Kind::Sequence: {
                std::set<std::size_t> at{from};
                for (const ReferenceNode& child : children) at = step(child, path, at);
                return at;
            }
            case Kind::Alternation: {
                std::set<std::size_t> all;
                for (const ReferenceNode& child : children) all.merge(child.ends(path, from));
                return all;
            }
            case Kind::Repetition: {
                // Beyond min + path length iterations only empty matches can be added.
                const int last = max >= 0 ? max : min + static_cast<int>(path.size()) + 1;
                std::set<std::size_t> at{from}, all;
                if (min == 0) all = at;
                for (int i = 1; i <= last; ++i) {
                    at = step(children.front(), path, at);
                    if (i >= min) all.insert(at.begin(), at.end());
                }
                return all;
            }
        }
        return {};
    }

    static std::set<std::size_t> step(const ReferenceNode& node, const Path& path, const std::set<std::size_t>& from) {
        std::set<std::size_t> to;
        for (std::size_t f : from) to.merge(node.ends(path, f));
        return to;
    }

    std::string print() const {
        switch (kind) {
            case Kind::Event: return text;
            case Kind::Sequence: {
                std::string out;
                for (const ReferenceNode& child : children)
                    out += child.kind == Kind::Alternation ? child.parenthesised() : child.print();
                return out;
            }
            case Kind::Alternation: {
                std::string out;
                for (const ReferenceNode& child : children) out += (out.empty() ? "" : " | ") + child.print();
                return out;
            }
            case Kind::Repetition: {
                const ReferenceNode& child = children.front();
                std::string out = child.kind == Kind::Event ? child.print() : child.parenthesised();
                if (min == 0 && max == -1) return out + "*";
                if (min == 1 && max == -1) return out + "+";
                if (min == 0 && max == 1) return out + "?";
                if (max == -1) return out + "{" + std::to_string(min) + ",}";
                if (min == max) return out + "{" + std::to_string(min) + "}";
                return out + "{" + std::to_string(min) + "," + std::to_string(max) + "}";
            }
        }
        return "";
    }

    std::string parenthesised() const {
        std::string out(1, '(');
        out += print();
        out += ')';
        return out;
    }
};

const char* const kExpressionLabels[] = {"key", "subsurface", "rim"};
const char* const kEventLabels[] = {"", "", "key", "subsurface", "fill"};

class RandomExpressions {
public:
    explicit RandomExpressions(std::uint32_t seed) : rng_(seed) {}

    int below(int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng_); }

    ReferenceNode node(int depth) {
        if (depth == 0 || below(10) < 4) return event();
        ReferenceNode node{static_cast<ReferenceNode::Kind>(1 + below(3))};
        if (node.kind == ReferenceNode::Kind::Repetition) {
            node.children.push_back(this->node(depth - 1));
            node.min = below(3);
            node.max = below(3) == 0 ? -1 : node.min + below(3);
        } else {
            for (int i = 0, n = 2 + below(2); i < n; ++i) node.children.push_back(this->node(depth - 1));
        }
        return node;
    }

    Path path() {
        Path path(static_cast<std::size_t>(below(8)));
        for (Event& event : path) event = randomEvent();
        return path;
    }

    Event randomEvent() {
        return {static_cast<EventType>(below(7)), static_cast<Scattering>(below(5)), kEventLabels[below(5)]};
    }

private:
    using Test = std::function<bool(const Event&)>;

    // One of a position's items: (text, test).
    std::pair<std::string, Test> item(int position) {
        if (position == 2) {
            const std::string label = kExpressionLabels[below(3)];
            return {"'" + label + "'", [label](const Event& e) { return e.label == label; }};
        }
        if (position == 0) {
            const int type = below(7);
            return {std::string(1, kTypeLetters[static_cast<std::size_t>(type)]),
                    [type](const Event& e) { return static_cast<int>(e.type) == type; }};
        }
        const int scattering = 1 + below(4);
        return {std::string(1, kScatteringLetters[static_cast<std::size_t>(scattering)]),
                [scattering](const Event& e) { return static_cast<int>(e.scattering) == scattering; }};
    }

    // A set of 1 to 3 items drawn by `draw`, maybe negated.
    std::pair<std::string, Test> set(const std::function<std::pair<std::string, Test>()>& draw) {
        const bool negated = below(2) == 0;
        std::string text = negated ? "[^" : "[";
        std::vector<Test> tests;
        for (int i = 0, n = 1 + below(3); i < n; ++i) {
            auto [itemText, test] = draw();
            text += itemText + (below(3) == 0 ? " " : "");
            tests.push_back(test);
        }
        return {text + "]", [tests, negated](const Event& e) {
                    bool any = false;
                    for (const Test& test : tests) any = any || test(e);
                    return any != negated;
                }};
    }

    ReferenceNode event() {
        ReferenceNode node{ReferenceNode::Kind::Event};
        const int kind = below(5);
        std::pair<std::string, Test> chosen;
        if (kind == 0) {
            chosen = {".", [](const Event&) { return true; }};
        } else if (kind == 1) {
            chosen = item(below(3));  // a shorthand: type or scattering letter, or a label
        } else if (kind == 2) {
            chosen = set([this] { return item(below(3)); });
        } else {  // <type scattering label>, trailing positions omitted
            std::string text = "<";
            std::vector<Test> tests;
            for (int position = 0, n = below(4); position < n; ++position) {
                if (below(6) == 0) position = 2;                           // a label may come early
                const int form = position == 2 ? 1 + below(3) : below(4);  // '.' would not be a label
                std::pair<std::string, Test> part =
                    form == 0   ? std::pair<std::string, Test>{".", [](const Event&) { return true; }}
                    : form == 1 ? set([this, position] { return item(position); })
                                : item(position);
                text += (below(2) ? " " : "") + part.first;
                tests.push_back(part.second);
            }
            chosen = {text + ">", [tests](const Event& e) {
                          for (const Test& test : tests)
                              if (!test(e)) return false;
                          return true;
                      }};
        }
        node.text = chosen.first;
        node.matches = chosen.second;
        return node;
    }

    std::mt19937 rng_;
};

TEST(LightPathExpression, AgreesWithAReferenceMatcherOnRandomExpressions) {
    RandomExpressions random(20261127);
    int compiled = 0, matched = 0, tooComplex = 0;
    for (int e = 0; e < 3000; ++e) {
        const ReferenceNode reference = random.node(4);
        const std::string text = reference.print();
        std::unique_ptr<LightPathExpression> expression;
        try {
            expression = std::make_unique<LightPathExpression>(text);
        } catch (const LpeSyntaxError& error) {
            ASSERT_NE(std::string(error.what()).find("too complex"), std::string::npos) << text << ": " << error.what();
            ++tooComplex;
            continue;
        }
        ++compiled;
        if (e % 10 == 0) {  // the automaton is minimal: an equivalent text gives as many states
            const LightPathExpression twice("(" + text + ")|" + text + "{1}");
            ASSERT_EQ(twice.stateCount(), expression->stateCount()) << text;
        }
        for (int p = 0; p < 40; ++p) {
            const Path path = random.path();
            const bool expected = reference.ends(path, 0).count(path.size()) > 0;
            matched += expected;
            ASSERT_EQ(accepts(*expression, path), expected) << text << " on a path of " << path.size() << " events";
        }
    }
    EXPECT_LT(tooComplex, 30);
    EXPECT_GT(matched, 3000);  // the paths do not all miss
    EXPECT_GT(compiled, 2900);
}

// Partitions of "C.*L": every path from a camera to a light must match exactly one expression.
const std::vector<std::vector<const char*>> kPartitions = {
    {"CL", "C[DGs].*L", "CS.*L", "C[^DGSs].*L"},  {"C.?L", "C.{2}L", "C.{3,5}L", "C.{6,}L"},
    {"C.*<L'key'>", "C.*<L.[^'key']>"},           {"C[^S]*L", "C.*S.*L"},
    {"C.*'subsurface'.*L", "C[^'subsurface']*L"}, {"C<RD>L", "C([^R]|<R[^D]>).*L", "C<RD>.+L", "CL"},
};

TEST(LightPathExpression, PartitionsOfCameraToLightPathsAcceptEachPathOnce) {
    RandomExpressions random(7);
    for (const std::vector<const char*>& texts : kPartitions) {
        std::vector<LightPathExpression> partition(texts.begin(), texts.end());
        std::vector<int> hits(partition.size(), 0);
        for (int p = 0; p < 5000; ++p) {
            Path path = random.path();
            path.insert(path.begin(), Event{EventType::Camera});
            path.push_back(Event{EventType::Light, Scattering::None, kEventLabels[random.below(5)]});
            int matches = 0;
            for (std::size_t i = 0; i < partition.size(); ++i) {
                const bool accepted = accepts(partition[i], path);
                matches += accepted;
                hits[i] += accepted;
            }
            ASSERT_EQ(matches, 1) << texts.front() << "... on a path of " << path.size() << " events";
        }
        for (std::size_t i = 0; i < partition.size(); ++i) EXPECT_GT(hits[i], 0) << texts[i];
    }
}

}  // namespace
}  // namespace fluence::integrators
