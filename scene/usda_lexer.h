// The USDA tokenizer (internal to the scene library).
//
// Splits USD text into tokens, tracking 1-based line and byte column of each, and whether a line
// break precedes it (USDA is line-sensitive in a few places: statements end at a newline or ';').
// Tokens:
//   Identifier  (XID_Start | '_') XID_Continue* with ':' and '::' namespace joins
//               ("xformOp:rotateXYZ", "Some::Type", "utf8_情報"): in ASCII [A-Za-z_][A-Za-z0-9_]*,
//               beyond it UTF-8 decoded and classed by unicode_xid.h. Malformed UTF-8 outside
//               strings, asset paths, paths and comments is an error.
//   Number      -?(digits[.digits]|.digits)([eE][+-]?digits)? and -inf; the value is the double
//               std::from_chars gives (scene/usda_number.h). The bare words inf and nan stay
//               identifiers (the value parser accepts them where a number is expected).
//   String      "..." '...' """...""" '''...''' with C-style escapes decoded.
//   Asset       @path@ or @@@path@@@ (the triple form may hold '@', and \@@@ for '@@@').
//   Path        <...>
//   Punct       one of ( ) [ ] { } = , : ; .
// Comments (# and // to end of line, /* ... */) and whitespace are skipped. The header line is
// not tokenized: the lexer starts after it.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace fluence::usd::detail {

enum class TokenKind { End, Identifier, Number, String, Asset, Path, Punct };

struct Token {
    TokenKind kind = TokenKind::End;
    char punct = 0;              // the character, for Punct
    std::string_view text;       // the token's source text
    std::string value;           // decoded content of String, Asset and Path tokens
    double number = 0.0;         // for Number
    bool integral = false;       // a Number written with digits only (no '.', exponent or inf)
    bool newlineBefore = false;  // a line break separates it from the previous token
    int line = 0;
    int column = 0;

    bool is(char c) const { return kind == TokenKind::Punct && punct == c; }
    bool isWord(std::string_view word) const { return kind == TokenKind::Identifier && text == word; }
};

// How a token is named in error messages: "'('", "'foo'", "string \"abc\"", "end of file".
std::string describe(const Token& token);

// Deepest nesting of prims, lists, tuples and dictionaries the parser accepts. The parser recurses
// once per level (about 1.2 KB of stack in a release build, 8.6 KB under AddressSanitizer), so the
// cap keeps the deepest accepted input well inside an 8 MB stack in every build; production
// layers nest a few tens of levels.
inline constexpr int kMaxNesting = 256;

// The elements Lexer::scanNumericRun reads.
struct NumericShape {
    int tupleSize = 0;      // numbers in each '(' ... ')' element; 0 for bare numbers
    bool integers = false;  // only integral numbers (digits) within [min, max]
    double min = 0, max = 0;
};

class Lexer {
public:
    // Tokenizes text[offset..], where offset is the start of line `line` (after the header).
    Lexer(std::string_view text, std::string file, std::size_t offset, int line);

    // The token `ahead` positions after the current one (at most kLookahead - 1).
    const Token& peek(std::size_t ahead = 0) {
        if (count_ <= ahead) fill(ahead);
        return buffer_[(head_ + ahead) % kLookahead];
    }
    Token take();
    void skip();  // drops the current token

    const std::string& file() const { return file_; }
    [[noreturn]] void fail(int line, int column, const std::string& message) const;
    [[noreturn]] void fail(const Token& at, const std::string& message) const { fail(at.line, at.column, message); }

    // The bulk path for numeric lists (most of a geometry layer's text): with no token looked
    // ahead, reads elements of `shape` straight from the text, each followed by ',' or by `close`,
    // and appends their numbers to `out`; it consumes `close` and returns true at the end of the
    // list. It stops and returns false before the first element that is not plain — a comment, a
    // line break before ',', inf or nan, a number the shape does not take, a malformed number, a
    // wrong count — leaving the lexer at that element: the token path reads it and reports any
    // error exactly. Numbers are read as the token path reads them (scene/usda_number.h).
    // (usda_lexer_numeric_run.cpp)
    bool scanNumericRun(const NumericShape& shape, char close, std::vector<double>& out);

    // Counts one more level of nesting opened at `at`; throws past kMaxNesting.
    void enterNesting(const Token& at);
    void leaveNesting() { --nesting_; }

private:
    static constexpr std::size_t kLookahead = 4;

    void fill(std::size_t ahead);
    void scan(Token& token);
    bool skipBlanks();            // spaces and line breaks; true when a line break was skipped
    bool skipSpaceAndComments();  // true when a line break was skipped
    // The length in bytes of the identifier character (start: one that may begin a name) at
    // text_[pos]; 0 when there is none. Throws at malformed UTF-8.
    std::size_t identifierCharAt(std::size_t pos, bool start) const;
    void skipIdentifierChars();
    [[noreturn]] void failInvalidCharacter(const Token& at) const;
    void scanIdentifier(Token& token);
    bool scanPlainElement(const NumericShape& shape, std::vector<double>& out);
    bool scanPlainNumber(const NumericShape& shape, std::vector<double>& out);
    void reserveForRun(const NumericShape& shape, char close, std::vector<double>& out) const;
    void scanNumber(Token& token);
    void scanString(Token& token);
    void scanAsset(Token& token);
    void scanPath(Token& token);
    void scanEscape(std::string& out);
    char current() const { return pos_ < text_.size() ? text_[pos_] : '\0'; }
    char at(std::size_t offset) const { return pos_ + offset < text_.size() ? text_[pos_ + offset] : '\0'; }
    void newline() { ++line_, lineStart_ = pos_; }  // call with pos_ just past the '\n'
    int column() const { return static_cast<int>(pos_ - lineStart_) + 1; }

    std::string_view text_;
    std::string file_;
    std::size_t pos_;
    std::size_t lineStart_;
    int line_;
    int nesting_ = 0;
    std::array<Token, kLookahead> buffer_;
    std::size_t head_ = 0;   // index of the current token in buffer_
    std::size_t count_ = 0;  // tokens scanned ahead
};

// RAII nesting level, for recursive parsing functions.
class NestingGuard {
public:
    NestingGuard(Lexer& lexer, const Token& at) : lexer_(lexer) { lexer_.enterNesting(at); }
    ~NestingGuard() { lexer_.leaveNesting(); }
    NestingGuard(const NestingGuard&) = delete;
    NestingGuard& operator=(const NestingGuard&) = delete;

private:
    Lexer& lexer_;
};

}  // namespace fluence::usd::detail
