#include "integrators/light_path_expression.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <string>
#include <tuple>
#include <utility>

namespace fluence::integrators {
namespace {

constexpr int kTypeCount = 7;
constexpr int kScatteringCount = 5;
constexpr std::uint8_t kAllTypes = (1u << kTypeCount) - 1;
constexpr std::uint8_t kAllScatterings = (1u << kScatteringCount) - 1;
constexpr int kMaxRepetition = 1000;
constexpr int kMaxNesting = 100;  // groups and stacked repetitions, which the parser and NFA recurse into
constexpr std::size_t kMaxNfaStates = 1u << 16;
constexpr std::size_t kMaxClosureSteps = 1u << 24;        // NFA states visited while determinizing (time and memory)
constexpr std::string_view kTypeLetters = "CRTVLOB";      // in EventType order
constexpr std::string_view kScatteringLetters = "-DGSs";  // in Scattering order (None has none)

[[noreturn]] void fail(std::size_t offset, const std::string& what) {
    throw LpeSyntaxError("column " + std::to_string(offset + 1) + ": " + what);
}

[[noreturn]] void failTooComplex(const std::string& why) { fail(0, "expression too complex (" + why + ")"); }

std::string quoted(char c) { return std::string("'") + c + "'"; }

int typeIndex(char c) {
    const auto at = kTypeLetters.find(c);
    return at == std::string_view::npos ? -1 : static_cast<int>(at);
}

int scatteringIndex(char c) {
    const auto at = kScatteringLetters.find(c);
    return at == std::string_view::npos || at == 0 ? -1 : static_cast<int>(at);
}

// A test on an event's custom label: any label, one of `names`, or (negated) none of them.
struct LabelTest {
    bool any = true;
    bool negated = false;
    std::vector<std::string> names;
};

// The events whose type is in `types`, scattering in `scatterings` (bit masks in enum order) and
// label passes `label`.
struct EventTest {
    std::uint8_t types = kAllTypes;
    std::uint8_t scatterings = kAllScatterings;
    LabelTest label;
};

// What one atom of the expression matches: an event passing any of `anyOf`, or, when negated, an
// event passing none of them.
struct EventPattern {
    std::vector<EventTest> anyOf;
    bool negated = false;
};

struct Node {
    enum class Kind { Event, Sequence, Alternation, Repetition } kind;
    int pattern = -1;  // Event: index into the parser's patterns
    std::vector<Node> children = {};
    int min = 0, max = 0;  // Repetition: bounds, max -1 for none
};

// Recursive descent over the text; every error names the column it found wrong.
class Parser {
public:
    explicit Parser(std::string_view text) : text_(text) {}

    Node parseWhole() {
        skipSpace();
        if (atEnd()) fail(0, "empty expression");
        Node root = parseAlternation();
        if (!atEnd()) fail(pos_, "unmatched " + quoted(text_[pos_]));  // parseSequence only stops at ')'
        return root;
    }

    std::vector<EventPattern> patterns;

private:
    void skipSpace() {
        while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
    }
    bool atEnd() {
        skipSpace();
        return pos_ == text_.size();
    }
    char peek() { return atEnd() ? '\0' : text_[pos_]; }

    Node parseAlternation() {
        Node first = parseSequence();
        if (peek() != '|') return first;
        Node alternation{Node::Kind::Alternation};
        alternation.children.push_back(std::move(first));
        while (peek() == '|') {
            ++pos_;
            alternation.children.push_back(parseSequence());
        }
        return alternation;
    }

    Node parseSequence() {
        Node sequence{Node::Kind::Sequence};
        while (!atEnd() && peek() != '|' && peek() != ')') sequence.children.push_back(parseRepeated());
        if (sequence.children.empty())
            fail(pos_, atEnd() ? "nothing to match at the end" : "nothing to match before " + quoted(peek()));
        if (sequence.children.size() == 1) return std::move(sequence.children.front());
        return sequence;
    }

    static bool isRepetition(char c) { return c == '*' || c == '+' || c == '?' || c == '{'; }

    Node parseRepeated() {
        if (isRepetition(peek())) fail(pos_, quoted(peek()) + " has nothing to repeat");
        Node node = parseAtom();
        const int outer = depth_;
        while (isRepetition(peek())) {
            enterLevel(pos_);
            Node repetition{Node::Kind::Repetition};
            switch (peek()) {
                case '*': repetition.min = 0, repetition.max = -1, ++pos_; break;
                case '+': repetition.min = 1, repetition.max = -1, ++pos_; break;
                case '?': repetition.min = 0, repetition.max = 1, ++pos_; break;
                default: std::tie(repetition.min, repetition.max) = parseBounds(); break;  // '{'
            }
            repetition.children.push_back(std::move(node));
            node = std::move(repetition);
        }
        depth_ = outer;
        return node;
    }

    // {n}, {n,m} or {n,}: (min, max), max -1 for none.
    std::pair<int, int> parseBounds() {
        const std::size_t open = pos_++;
        const int min = parseNumber("expected a number after '{'");
        int max = min;
        if (peek() == ',') {
            ++pos_;
            max = peek() == '}' ? -1 : parseNumber("expected a number or '}' after ','");
        }
        if (atEnd()) fail(open, "unclosed '{'");
        if (peek() != '}') fail(pos_, "expected '}'");
        ++pos_;
        if (max != -1 && max < min)
            fail(open, "reversed repetition bounds (" + std::to_string(min) + " > " + std::to_string(max) + ")");
        return {min, max};
    }

    void enterLevel(std::size_t at) {
        if (++depth_ > kMaxNesting)
            fail(at, "groups and repetitions nested more than " + std::to_string(kMaxNesting) + " deep");
    }

    int parseNumber(const char* whatIfMissing) {
        if (!std::isdigit(static_cast<unsigned char>(peek()))) fail(pos_, whatIfMissing);
        const std::size_t begin = pos_;
        long value = 0;
        while (pos_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[pos_]))) {
            value = std::min<long>(value * 10 + (text_[pos_] - '0'), kMaxRepetition + 1);
            ++pos_;
        }
        if (value > kMaxRepetition) fail(begin, "repetition bound above " + std::to_string(kMaxRepetition));
        return static_cast<int>(value);
    }

    Node parseAtom() {
        const char c = peek();
        switch (c) {
            case '(': {
                const std::size_t open = pos_++;
                enterLevel(open);
                Node inner = parseAlternation();
                if (atEnd()) fail(open, "unclosed '('");
                ++pos_;  // ')': parseSequence stops only there, at '|' (consumed) or at the end
                --depth_;
                return inner;
            }
            case '<': return eventNode(parseEvent());
            case '[': return eventNode(parseShorthandSet());
            case '\'': {
                EventTest test;
                test.label = {false, false, {parseLabel()}};
                return eventNode({{test}});
            }
            case '.': ++pos_; return eventNode({{EventTest{}}});
            case '>':
            case ']':
            case '}': fail(pos_, "unmatched " + quoted(c));
            default: return eventNode({{parseShorthand()}});
        }
    }

    Node eventNode(EventPattern pattern) {
        patterns.push_back(std::move(pattern));
        Node node{Node::Kind::Event};
        node.pattern = static_cast<int>(patterns.size()) - 1;
        return node;
    }

    // A type or scattering letter outside angle brackets.
    EventTest parseShorthand() {
        const char c = text_[pos_];
        EventTest test;
        if (const int type = typeIndex(c); type >= 0) {
            test.types = static_cast<std::uint8_t>(1u << type);
        } else if (const int scattering = scatteringIndex(c); scattering >= 0) {
            test.scatterings = static_cast<std::uint8_t>(1u << scattering);
        } else {
            fail(pos_, std::isalpha(static_cast<unsigned char>(c)) ? "unknown letter " + quoted(c)
                                                                   : "unexpected character " + quoted(c));
        }
        ++pos_;
        return test;
    }

    std::string parseLabel() {
        const std::size_t open = pos_;
        const std::size_t close = text_.find('\'', open + 1);
        if (close == std::string_view::npos) fail(open, "unclosed quote");
        if (close == open + 1) fail(open, "empty label");
        pos_ = close + 1;
        return std::string(text_.substr(open + 1, close - open - 1));
    }

    // Opens a set at '[': whether it is negated ('^').
    bool openSet() {
        ++pos_;
        if (peek() != '^') return false;
        ++pos_;
        return true;
    }

    // Checks the set opened at `open` goes on: false at its ']' (consumed), fails at its end or at
    // a character no set holds.
    bool setContinues(std::size_t open, bool empty) {
        const char c = peek();
        if (c == ']') {
            if (empty) fail(open, "empty set");
            ++pos_;
            return false;
        }
        if (c == '.') fail(pos_, "'.' in a set (a set lists letters and labels)");
        if (c != '\'' && !std::isalpha(static_cast<unsigned char>(c))) fail(open, "unclosed '['");
        return true;
    }

    // [..] or [^..] of shorthands outside angle brackets.
    EventPattern parseShorthandSet() {
        const std::size_t open = pos_;
        EventPattern pattern;
        pattern.negated = openSet();
        while (setContinues(open, pattern.anyOf.empty())) {
            if (peek() == '\'') {
                EventTest test;
                test.label = {false, false, {parseLabel()}};
                pattern.anyOf.push_back(std::move(test));
            } else {
                pattern.anyOf.push_back(parseShorthand());
            }
        }
        return pattern;
    }

    // <type scattering label>, each position optional at the end; a label (or a set of labels)
    // may come early, the positions it skips being wildcards.
    EventPattern parseEvent() {
        const std::size_t open = pos_++;
        EventTest test;
        for (int position = 0;; ++position) {
            const char c = peek();
            if (c == '>') break;
            if (c != '.' && c != '[' && c != '\'' && !std::isalpha(static_cast<unsigned char>(c)))
                fail(open, "unclosed '<'");
            if (position == 3) fail(pos_, "an event ends after its label (positions: type, scattering, label)");
            if (labelComes()) position = 2;
            parsePosition(position, test);
        }
        ++pos_;
        return {{std::move(test)}};
    }

    // Whether the next position is a label or a set opening with one.
    bool labelComes() const {
        std::size_t at = pos_;
        auto skipSpace = [&] {
            while (at < text_.size() && std::isspace(static_cast<unsigned char>(text_[at]))) ++at;
        };
        if (text_[at] == '[') {
            ++at;
            skipSpace();
            if (at < text_.size() && text_[at] == '^') ++at;
            skipSpace();
        }
        return at < text_.size() && text_[at] == '\'';
    }

    void parsePosition(int position, EventTest& test) {
        if (peek() == '.') {
            ++pos_;
            return;
        }
        std::uint8_t mask = 0;
        LabelTest label{false, false, {}};
        bool negated = false;
        if (peek() == '[') {
            const std::size_t open = pos_;
            negated = openSet();
            while (setContinues(open, mask == 0 && label.names.empty())) parsePositionItem(position, mask, label);
        } else {
            parsePositionItem(position, mask, label);
        }
        if (position == 0) test.types = negated ? static_cast<std::uint8_t>(~mask & kAllTypes) : mask;
        if (position == 1) test.scatterings = negated ? static_cast<std::uint8_t>(~mask & kAllScatterings) : mask;
        if (position == 2) {
            label.negated = negated;
            test.label = std::move(label);
        }
    }

    // One letter or label in `position`, added to `mask` (type or scattering) or `label`.
    void parsePositionItem(int position, std::uint8_t& mask, LabelTest& label) {
        const char c = peek();
        if (c == '\'') {
            if (position != 2) fail(pos_, "a label belongs in the third position");
            label.names.push_back(parseLabel());
            return;
        }
        const int type = typeIndex(c), scattering = scatteringIndex(c);
        if (position == 2) fail(pos_, "expected a quoted label in the third position, not " + quoted(c));
        if (type < 0 && scattering < 0) fail(pos_, "unknown letter " + quoted(c));
        if (position == 0 && type < 0) fail(pos_, quoted(c) + " is a scattering, not an event type");
        if (position == 1 && scattering < 0) fail(pos_, quoted(c) + " is an event type, not a scattering");
        mask |= static_cast<std::uint8_t>(1u << (position == 0 ? type : scattering));
        ++pos_;
    }

    std::string_view text_;
    std::size_t pos_ = 0;
    int depth_ = 0;  // open groups and stacked repetitions
};

bool passes(const LabelTest& test, const std::string* label) {
    if (test.any) return true;
    const bool named = label && std::find(test.names.begin(), test.names.end(), *label) != test.names.end();
    return named != test.negated;
}

// Whether `pattern` matches the symbol (type, scattering, label); label nullptr for "any other".
bool matches(const EventPattern& pattern, int type, int scattering, const std::string* label) {
    const bool any = std::any_of(pattern.anyOf.begin(), pattern.anyOf.end(), [&](const EventTest& test) {
        return (test.types >> type & 1u) && (test.scatterings >> scattering & 1u) && passes(test.label, label);
    });
    return any != pattern.negated;
}

// A Thompson NFA: each state has epsilon moves and at most one move on an event pattern.
struct Nfa {
    struct State {
        std::vector<int> epsilon;
        int pattern = -1;
        int target = -1;
    };
    struct Fragment {
        int start, end;
    };
    std::vector<State> states;

    int add() {
        if (states.size() == kMaxNfaStates)
            failTooComplex("its repetitions expand to more than " + std::to_string(kMaxNfaStates) + " steps");
        states.emplace_back();
        return static_cast<int>(states.size()) - 1;
    }
    void link(int from, int to) { states[static_cast<std::size_t>(from)].epsilon.push_back(to); }

    Fragment build(const Node& node) {
        switch (node.kind) {
            case Node::Kind::Event: {
                const int start = add(), end = add();
                states[static_cast<std::size_t>(start)].pattern = node.pattern;
                states[static_cast<std::size_t>(start)].target = end;
                return {start, end};
            }
            case Node::Kind::Sequence: {
                Fragment whole = build(node.children.front());
                for (std::size_t i = 1; i < node.children.size(); ++i) {
                    const Fragment next = build(node.children[i]);
                    link(whole.end, next.start);
                    whole.end = next.end;
                }
                return whole;
            }
            case Node::Kind::Alternation: {
                const int start = add(), end = add();
                for (const Node& child : node.children) {
                    const Fragment branch = build(child);
                    link(start, branch.start);
                    link(branch.end, end);
                }
                return {start, end};
            }
            case Node::Kind::Repetition: {
                const Node& body = node.children.front();
                const int start = add();
                int end = start;
                for (int i = 0; i < node.min; ++i) end = append(end, body);
                if (node.max == -1) {
                    const int loop = add();
                    link(end, loop);
                    link(append(loop, body), loop);
                    return {start, loop};
                }
                const int exit = add();
                for (int i = node.min; i < node.max; ++i) {
                    link(end, exit);
                    end = append(end, body);
                }
                link(end, exit);
                return {start, exit};
            }
        }
        return {-1, -1};
    }

    // A fresh copy of `node` entered from `from`: its end.
    int append(int from, const Node& node) {
        const Fragment copy = build(node);
        link(from, copy.start);
        return copy.end;
    }
};

// A DFA over symbol classes: transitions[state * classes + class], -1 for none.
struct Dfa {
    std::vector<int> transitions;
    std::vector<std::uint8_t> accepting;
    int stateCount() const { return static_cast<int>(accepting.size()); }
};

// Subset construction. A DFA state is the set of NFA states reachable by the path so far, kept
// as its sorted "important" states (those with a move on a pattern, and the accepting end): two
// closures with the same important states behave alike.
Dfa determinize(const Nfa& nfa, Nfa::Fragment whole, const std::vector<std::vector<char>>& patternMatchesClass,
                std::size_t classes) {
    std::vector<std::uint32_t> visited(nfa.states.size(), 0);
    std::uint32_t visit = 0;
    std::size_t steps = 0;
    auto closure = [&](std::vector<int> set) {
        ++visit;
        for (int s : set) visited[static_cast<std::size_t>(s)] = visit;
        for (std::size_t i = 0; i < set.size(); ++i) {
            for (int t : nfa.states[static_cast<std::size_t>(set[i])].epsilon) {
                if (visited[static_cast<std::size_t>(t)] != visit) {
                    visited[static_cast<std::size_t>(t)] = visit;
                    set.push_back(t);
                }
            }
        }
        steps += set.size();
        if (steps > kMaxClosureSteps) failTooComplex("building its automaton would take too long");
        std::erase_if(set,
                      [&](int s) { return nfa.states[static_cast<std::size_t>(s)].pattern < 0 && s != whole.end; });
        std::sort(set.begin(), set.end());
        return set;
    };

    Dfa dfa;
    std::map<std::vector<int>, int> ids;
    std::vector<const std::vector<int>*> sets;  // keys of ids, by id
    auto idOf = [&](std::vector<int> set) {
        const auto [it, added] = ids.emplace(std::move(set), static_cast<int>(sets.size()));
        if (added) {
            if (sets.size() == static_cast<std::size_t>(LightPathExpression::kMaxStates))
                failTooComplex("its automaton would need more than " + std::to_string(LightPathExpression::kMaxStates) +
                               " states");
            sets.push_back(&it->first);
            dfa.accepting.push_back(std::binary_search(it->first.begin(), it->first.end(), whole.end) ? 1 : 0);
        }
        return it->second;
    };
    idOf(closure({whole.start}));
    for (std::size_t state = 0; state < sets.size(); ++state) {
        for (std::size_t c = 0; c < classes; ++c) {
            std::vector<int> moved;
            for (int s : *sets[state]) {
                const Nfa::State& nfaState = nfa.states[static_cast<std::size_t>(s)];
                if (nfaState.pattern >= 0 && patternMatchesClass[static_cast<std::size_t>(nfaState.pattern)][c])
                    moved.push_back(nfaState.target);
            }
            dfa.transitions.push_back(moved.empty() ? -1 : idOf(closure(std::move(moved))));
        }
    }
    return dfa;
}

// Hopcroft's partition refinement of a DFA's states: blocks are ranges of `members`, the marked
// members of a block at the front of its range.
class Partition {
public:
    // States 0..count-1, split into the blocks given by `initialBlock` (0-based, dense).
    Partition(std::size_t count, const std::vector<int>& initialBlock)
        : members_(count), location_(count), blockOf_(initialBlock) {
        const int blocks = 1 + *std::max_element(initialBlock.begin(), initialBlock.end());
        first_.assign(static_cast<std::size_t>(blocks) + 1, 0);
        for (int b : initialBlock) ++first_[static_cast<std::size_t>(b) + 1];
        for (int b = 0; b < blocks; ++b) first_[static_cast<std::size_t>(b) + 1] += first_[static_cast<std::size_t>(b)];
        end_.assign(first_.begin() + 1, first_.end());
        first_.pop_back();
        std::vector<int> fill(first_.begin(), first_.end());
        for (std::size_t s = 0; s < count; ++s)
            place(static_cast<int>(s), fill[static_cast<std::size_t>(blockOf_[s])]++);
        marked_.assign(first_.size(), 0);
    }

    int blockCount() const { return static_cast<int>(first_.size()); }
    int blockOf(int state) const { return blockOf_[static_cast<std::size_t>(state)]; }
    std::vector<int> membersOf(int block) const {
        return {members_.begin() + first_[static_cast<std::size_t>(block)],
                members_.begin() + end_[static_cast<std::size_t>(block)]};
    }
    int sizeOf(int block) const {
        return end_[static_cast<std::size_t>(block)] - first_[static_cast<std::size_t>(block)];
    }

    void mark(int state) {
        const auto b = static_cast<std::size_t>(blockOf(state));
        const int front = first_[b] + marked_[b];
        if (location_[static_cast<std::size_t>(state)] < front) return;  // already marked
        const int other = members_[static_cast<std::size_t>(front)];
        place(other, location_[static_cast<std::size_t>(state)]);
        place(state, front);
        if (marked_[b]++ == 0) touched_.push_back(static_cast<int>(b));
    }

    // Splits every block with marked and unmarked members; calls split(old, new) for each, the new
    // block holding the marked ones. Clears the marks.
    template <class OnSplit>
    void split(OnSplit&& onSplit) {
        for (int b : touched_) {
            const auto old = static_cast<std::size_t>(b);
            if (first_[old] + marked_[old] < end_[old]) {
                const int created = blockCount();
                first_.push_back(first_[old]);
                end_.push_back(first_[old] + marked_[old]);
                marked_.push_back(0);
                first_[old] = end_.back();
                for (int i = first_.back(); i < end_.back(); ++i)
                    blockOf_[static_cast<std::size_t>(members_[static_cast<std::size_t>(i)])] = created;
                onSplit(b, created);
            }
            marked_[old] = 0;
        }
        touched_.clear();
    }

private:
    void place(int state, int at) {
        members_[static_cast<std::size_t>(at)] = state;
        location_[static_cast<std::size_t>(state)] = at;
    }

    std::vector<int> members_, location_, blockOf_;
    std::vector<int> first_, end_, marked_;  // per block
    std::vector<int> touched_;               // blocks with marked members
};

// The minimal DFA equivalent to `dfa`, without the states from which no accepting state can be
// reached (those are merged with the missing transitions' sink and dropped, becoming -1). States
// are numbered in order of their first member, so the start (state 0) keeps 0 unless it is dead.
Dfa minimize(const Dfa& dfa, std::size_t classes) {
    const auto n = static_cast<std::size_t>(dfa.stateCount());
    const int sink = static_cast<int>(n);
    auto target = [&](std::size_t s, std::size_t c) {
        const int t = s < n ? dfa.transitions[s * classes + c] : -1;
        return t < 0 ? sink : t;
    };
    // Predecessors per (class, state), sink included: sources[offsets[c * (n + 1) + t] ...].
    std::vector<int> offsets((n + 1) * classes + 1, 0), sources((n + 1) * classes);
    for (std::size_t c = 0; c < classes; ++c)
        for (std::size_t s = 0; s <= n; ++s) ++offsets[c * (n + 1) + static_cast<std::size_t>(target(s, c)) + 1];
    for (std::size_t i = 1; i < offsets.size(); ++i) offsets[i] += offsets[i - 1];
    std::vector<int> fill(offsets.begin(), offsets.end() - 1);
    for (std::size_t c = 0; c < classes; ++c)
        for (std::size_t s = 0; s <= n; ++s)
            sources[static_cast<std::size_t>(fill[c * (n + 1) + static_cast<std::size_t>(target(s, c))]++)] =
                static_cast<int>(s);

    std::vector<int> initial(n + 1, 0);
    for (std::size_t s = 0; s < n; ++s) initial[s] = dfa.accepting[s];
    Partition partition(n + 1, initial);
    std::vector<int> work;
    std::vector<char> waiting;
    for (int b = 0; b < partition.blockCount(); ++b) work.push_back(b), waiting.push_back(1);
    while (!work.empty()) {
        const int splitter = work.back();
        work.pop_back();
        waiting[static_cast<std::size_t>(splitter)] = 0;
        const std::vector<int> into = partition.membersOf(splitter);
        for (std::size_t c = 0; c < classes; ++c) {
            for (int t : into) {
                const std::size_t at = c * (n + 1) + static_cast<std::size_t>(t);
                for (int i = offsets[at]; i < offsets[at + 1]; ++i)
                    partition.mark(sources[static_cast<std::size_t>(i)]);
            }
            partition.split([&](int old, int created) {
                waiting.push_back(0);
                const int smaller =
                    waiting[static_cast<std::size_t>(old)] || partition.sizeOf(created) < partition.sizeOf(old)
                        ? created
                        : old;
                work.push_back(smaller);
                waiting[static_cast<std::size_t>(smaller)] = 1;
            });
        }
    }

    const int dead = partition.blockOf(sink);
    std::vector<int> number(static_cast<std::size_t>(partition.blockCount()), -1);
    int states = 0;
    for (std::size_t s = 0; s < n; ++s) {
        const int b = partition.blockOf(static_cast<int>(s));
        if (b != dead && number[static_cast<std::size_t>(b)] < 0) number[static_cast<std::size_t>(b)] = states++;
    }
    Dfa minimal;
    minimal.accepting.assign(static_cast<std::size_t>(states), 0);
    minimal.transitions.assign(static_cast<std::size_t>(states) * classes, -1);
    for (std::size_t s = 0; s < n; ++s) {
        const int b = number[static_cast<std::size_t>(partition.blockOf(static_cast<int>(s)))];
        if (b < 0) continue;
        minimal.accepting[static_cast<std::size_t>(b)] = dfa.accepting[s];
        for (std::size_t c = 0; c < classes; ++c)
            minimal.transitions[static_cast<std::size_t>(b) * classes + c] =
                number[static_cast<std::size_t>(partition.blockOf(target(s, c)))];
    }
    return minimal;
}

}  // namespace

LightPathExpression::LightPathExpression(std::string_view text) : text_(text) {
    Parser parser(text);
    const Node root = parser.parseWhole();

    for (const EventPattern& pattern : parser.patterns)
        for (const EventTest& test : pattern.anyOf)
            labels_.insert(labels_.end(), test.label.names.begin(), test.label.names.end());
    std::sort(labels_.begin(), labels_.end());
    labels_.erase(std::unique(labels_.begin(), labels_.end()), labels_.end());

    // The alphabet, merged into classes of symbols that every pattern treats alike.
    const std::size_t labelSlots = labels_.size() + 1;
    std::map<std::vector<char>, std::uint32_t> classOfSignature;
    std::vector<std::vector<char>> classSignatures;
    for (int type = 0; type < kTypeCount; ++type) {
        for (int scattering = 0; scattering < kScatteringCount; ++scattering) {
            for (std::size_t label = 0; label < labelSlots; ++label) {
                const std::string* name = label < labels_.size() ? &labels_[label] : nullptr;
                std::vector<char> signature;
                for (const EventPattern& pattern : parser.patterns)
                    signature.push_back(matches(pattern, type, scattering, name) ? 1 : 0);
                const auto [it, added] =
                    classOfSignature.emplace(signature, static_cast<std::uint32_t>(classSignatures.size()));
                if (added) classSignatures.push_back(std::move(signature));
                symbolClass_.push_back(it->second);
            }
        }
    }
    classCount_ = classSignatures.size();
    std::vector<std::vector<char>> patternMatchesClass(parser.patterns.size(), std::vector<char>(classCount_));
    for (std::size_t c = 0; c < classCount_; ++c)
        for (std::size_t p = 0; p < parser.patterns.size(); ++p) patternMatchesClass[p][c] = classSignatures[c][p];

    Nfa nfa;
    const Nfa::Fragment whole = nfa.build(root);
    Dfa dfa = minimize(determinize(nfa, whole, patternMatchesClass, classCount_), classCount_);
    transitions_ = std::move(dfa.transitions);
    accepting_ = std::move(dfa.accepting);
    start_ = accepting_.empty() ? kDead : 0;
}

}  // namespace fluence::integrators
