// Lexer::scanNumericRun, the lexer's bulk path for numeric lists (see usda_lexer.h).
#include <algorithm>
#include <cstring>

#include "scene/usda_chars.h"
#include "scene/usda_lexer.h"
#include "scene/usda_number.h"

namespace fluence::usd::detail {

bool Lexer::scanNumericRun(const NumericShape& shape, char close, std::vector<double>& out) {
    if (count_ != 0) return false;
    if (out.empty()) reserveForRun(shape, close, out);
    while (true) {
        // Where the element starts, to go back to when it is not plain.
        std::size_t pos = pos_, lineStart = lineStart_, size = out.size();
        int line = line_;
        skipBlanks();
        if (current() == close) {  // the end, after '[' or a trailing ','
            ++pos_;
            return true;
        }
        if (scanPlainElement(shape, out)) {
            bool newlineBefore = skipBlanks();
            if (current() == close) {
                ++pos_;
                return true;
            }
            if (current() == ',' && !newlineBefore) {
                ++pos_;
                continue;
            }
        }
        pos_ = pos, lineStart_ = lineStart, line_ = line;
        out.resize(size);
        return false;
    }
}

bool Lexer::scanPlainElement(const NumericShape& shape, std::vector<double>& out) {
    if (shape.tupleSize == 0) return scanPlainNumber(shape, out);
    if (current() != '(') return false;
    ++pos_;
    for (int i = 0; i < shape.tupleSize; ++i) {
        skipBlanks();
        if (!scanPlainNumber(shape, out)) return false;
        bool newlineBefore = skipBlanks();
        char expected = i + 1 < shape.tupleSize ? ',' : ')';
        if (current() != expected || (expected == ',' && newlineBefore)) return false;
        ++pos_;
    }
    return true;
}

bool Lexer::scanPlainNumber(const NumericShape& shape, std::vector<double>& out) {
    const char* first = text_.data() + pos_;
    const char* last = text_.data() + text_.size();
    ParsedNumber number = parseNumber(first, last);
    if (number.end == first || !number.inRange) return false;
    // Only a blank or a separator may follow a plain number ("1.2.3", "1e", "2x" are not).
    char next = number.end < last ? *number.end : ' ';
    if (!isIn(next, kBlank | kNewline) && next != ',' && next != ')' && next != ']') return false;
    if (shape.integers && (!number.integral || number.value < shape.min || number.value > shape.max)) {
        return false;
    }
    out.push_back(number.value);
    pos_ += static_cast<std::size_t>(number.end - first);
    return true;
}

// Reserves room for the elements up to the first `close`: one per '(' for tuples, one per ','
// (and one more) for bare numbers; at most one per shortest possible element.
void Lexer::reserveForRun(const NumericShape& shape, char close, std::vector<double>& out) const {
    const char* first = text_.data() + pos_;
    const void* found = std::memchr(first, close, text_.size() - pos_);
    if (!found) return;
    const char* last = static_cast<const char*>(found);
    auto elements =
        static_cast<std::size_t>(shape.tupleSize ? std::count(first, last, '(') : std::count(first, last, ',') + 1);
    std::size_t shortest = shape.tupleSize ? 2 * shape.tupleSize + 1 : 1;
    elements = std::min(elements, static_cast<std::size_t>(last - first) / shortest + 1);
    out.reserve(elements * static_cast<std::size_t>(std::max(shape.tupleSize, 1)));
}

}  // namespace fluence::usd::detail
