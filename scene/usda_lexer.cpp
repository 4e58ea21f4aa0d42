#include "scene/usda_lexer.h"

#include <limits>
#include <utility>

#include "scene/unicode_xid.h"
#include "scene/usda_chars.h"
#include "scene/usda_number.h"
#include "scene/usda_parser.h"
#include "scene/utf8.h"

namespace fluence::usd::detail {

namespace {

bool isDigit(char c) { return isIn(c, kDigit); }
bool isAscii(char c) { return static_cast<unsigned char>(c) < 0x80; }

int hexDigit(char c) {
    if (isDigit(c)) return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

std::string quoteForMessage(std::string_view s, std::size_t limit = 40) {
    std::string out;
    for (char c : s.substr(0, limit)) {
        if (c == '\n')
            out += "\\n";
        else if (c == '"')
            out += "\\\"";
        else
            out += c;
    }
    if (s.size() > limit) out += "...";
    return out;
}

}  // namespace

std::string describe(const Token& token) {
    switch (token.kind) {
        case TokenKind::End: return "end of file";
        case TokenKind::Identifier: return std::string("'").append(token.text).append("'");
        case TokenKind::Number: return "number " + std::string(token.text);
        case TokenKind::String: return "string \"" + quoteForMessage(token.value) + "\"";
        case TokenKind::Asset: return "asset path @" + quoteForMessage(token.value) + "@";
        case TokenKind::Path: return "path <" + quoteForMessage(token.value) + ">";
        case TokenKind::Punct: return std::string("'") + token.punct + "'";
    }
    return "token";
}

Lexer::Lexer(std::string_view text, std::string file, std::size_t offset, int line)
    : text_(text), file_(std::move(file)), pos_(offset), lineStart_(offset), line_(line) {}

void Lexer::fail(int line, int column, const std::string& message) const {
    throw ParseError(SourceLocation{file_, line, column}, message);
}

void Lexer::enterNesting(const Token& at) {
    if (++nesting_ > kMaxNesting) {
        fail(at, "nesting deeper than " + std::to_string(kMaxNesting) + " levels");
    }
}

void Lexer::fill(std::size_t ahead) {
    while (count_ <= ahead) {
        scan(buffer_[(head_ + count_) % kLookahead]);
        ++count_;
    }
}

Token Lexer::take() {
    peek();
    Token token = std::move(buffer_[head_]);
    head_ = (head_ + 1) % kLookahead;
    --count_;
    return token;
}

void Lexer::skip() {
    peek();
    head_ = (head_ + 1) % kLookahead;
    --count_;
}

bool Lexer::skipBlanks() {
    bool sawNewline = false;
    while (pos_ < text_.size() && isIn(text_[pos_], kBlank | kNewline)) {
        if (text_[pos_++] == '\n') {
            newline();
            sawNewline = true;
        }
    }
    return sawNewline;
}

bool Lexer::skipSpaceAndComments() {
    bool sawNewline = false;
    while (pos_ < text_.size()) {
        char c = text_[pos_];
        if (isIn(c, kBlank | kNewline)) {
            sawNewline = skipBlanks() || sawNewline;
        } else if (c == '#' || (c == '/' && at(1) == '/')) {
            while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
        } else if (c == '/' && at(1) == '*') {
            int line = line_, col = column();
            pos_ += 2;
            while (pos_ < text_.size() && !(text_[pos_] == '*' && at(1) == '/')) {
                if (text_[pos_++] == '\n') {
                    newline();
                    sawNewline = true;
                }
            }
            if (pos_ >= text_.size()) fail(line, col, "unterminated '/*' comment");
            pos_ += 2;
        } else {
            break;
        }
    }
    return sawNewline;
}

void Lexer::scan(Token& token) {
    // The slot is reused: reset every field (value keeps its capacity).
    token.kind = TokenKind::End;
    token.punct = 0;
    token.value.clear();
    token.number = 0.0;
    token.integral = false;
    token.newlineBefore = skipSpaceAndComments();
    token.line = line_;
    token.column = column();
    std::size_t start = pos_;
    char c = current();
    if (pos_ >= text_.size()) {
        // End of input: the kind stays End.
    } else if (identifierCharAt(pos_, true)) {
        scanIdentifier(token);
    } else if (isDigit(c) || (c == '.' && isDigit(at(1))) ||
               (c == '-' &&
                (isDigit(at(1)) || (at(1) == '.' && isDigit(at(2))) || text_.substr(pos_ + 1, 3) == "inf"))) {
        scanNumber(token);
    } else if (c == '"' || c == '\'') {
        scanString(token);
    } else if (c == '@') {
        scanAsset(token);
    } else if (c == '<') {
        scanPath(token);
    } else if (isIn(c, kPunct)) {
        token.kind = TokenKind::Punct;
        token.punct = c;
        ++pos_;
    } else {
        failInvalidCharacter(token);
    }
    token.text = text_.substr(start, pos_ - start);
}

void Lexer::failInvalidCharacter(const Token& at) const {
    char c = current();
    unsigned char byte = static_cast<unsigned char>(c);
    if (byte >= 0x20 && byte < 0x7f) fail(at, std::string("invalid character '") + c + "'");
    if (isAscii(c)) {
        static const char* hex = "0123456789abcdef";
        fail(at, std::string("invalid character 0x") + hex[byte >> 4] + hex[byte & 15]);
    }
    char32_t codePoint = decodeUtf8(text_, pos_).codePoint;  // well-formed: identifierCharAt said
    fail(at, "invalid character " + describeCodePoint(codePoint) +
                 (isXidContinue(codePoint) ? " (a name cannot start with it)" : ""));
}

std::size_t Lexer::identifierCharAt(std::size_t pos, bool start) const {
    if (pos >= text_.size()) return 0;
    char c = text_[pos];
    if (isAscii(c)) return isIn(c, start ? kLetter : kLetter | kDigit) ? 1 : 0;
    Utf8Char decoded = decodeUtf8(text_, pos);
    if (!decoded.length) {
        fail(line_, static_cast<int>(pos - lineStart_) + 1, describeMalformedUtf8(text_, pos));
    }
    bool accepted = start ? isXidStart(decoded.codePoint) : isXidContinue(decoded.codePoint);
    return accepted ? decoded.length : 0;
}

void Lexer::skipIdentifierChars() {
    while (std::size_t length = identifierCharAt(pos_, false)) pos_ += length;
}

void Lexer::scanIdentifier(Token& token) {
    token.kind = TokenKind::Identifier;
    std::size_t start = pos_;
    skipIdentifierChars();
    // Namespace joins: "a:b" and "a::b", each followed by more identifier characters.
    while (current() == ':') {
        std::size_t colons = at(1) == ':' ? 2 : 1;
        if (!identifierCharAt(pos_ + colons, false)) break;
        pos_ += colons;
        skipIdentifierChars();
    }
    // A non-ASCII character right after a name could only be part of it, and is not allowed there.
    if (!isAscii(current())) {
        char32_t codePoint = decodeUtf8(text_, pos_).codePoint;
        fail(line_, column(),
             "invalid character " + describeCodePoint(codePoint) + " in the name '" +
                 std::string(text_.substr(start, pos_ - start)) +
                 "' (names are letters, digits and '_': Unicode XID_Continue)");
    }
}

void Lexer::scanNumber(Token& token) {
    token.kind = TokenKind::Number;
    std::size_t start = pos_;
    if (current() == '-' && text_.substr(pos_ + 1, 3) == "inf") {
        pos_ += 4;
        token.number = -std::numeric_limits<double>::infinity();
    } else {
        const char* first = text_.data() + start;
        ParsedNumber number = parseNumber(first, text_.data() + text_.size());
        token.integral = number.integral;
        token.number = number.value;
        pos_ += static_cast<std::size_t>(number.end - first);
        if (!number.inRange) {
            fail(token, "number " + std::string(first, number.end) + " is out of range");
        }
    }
    // A number runs into the next token only when it is malformed: "1.2.3", "12abc", "1e".
    if (identifierCharAt(pos_, false) || (current() == '.' && isDigit(at(1)))) {
        std::size_t end = pos_;
        while (end < text_.size() &&
               (isIn(text_[end], kLetter | kDigit) || !isAscii(text_[end]) || text_[end] == '.')) {
            ++end;
        }
        fail(token, "malformed number '" + std::string(text_.substr(start, end - start)) + "'");
    }
}

void Lexer::scanEscape(std::string& out) {
    // At the character after a backslash.
    char c = current();
    ++pos_;
    switch (c) {
        case 'n': out += '\n'; return;
        case 't': out += '\t'; return;
        case 'r': out += '\r'; return;
        case 'a': out += '\a'; return;
        case 'b': out += '\b'; return;
        case 'f': out += '\f'; return;
        case 'v': out += '\v'; return;
        case 'x': {
            int value = 0, digits = 0;
            while (digits < 2 && hexDigit(current()) >= 0) {
                value = value * 16 + hexDigit(current());
                ++pos_, ++digits;
            }
            out += digits ? static_cast<char>(value) : 'x';
            return;
        }
        default:
            if (c >= '0' && c <= '7') {
                int value = c - '0', digits = 1;
                while (digits < 3 && current() >= '0' && current() <= '7') {
                    value = value * 8 + (current() - '0');
                    ++pos_, ++digits;
                }
                out += static_cast<char>(value);
                return;
            }
            if (c == '\n') newline();
            out += c;  // \\ \" \' and any other character stand for themselves
    }
}

void Lexer::scanString(Token& token) {
    token.kind = TokenKind::String;
    char quote = current();
    bool triple = at(1) == quote && at(2) == quote;
    pos_ += triple ? 3 : 1;
    while (true) {
        if (pos_ >= text_.size()) fail(token, "unterminated string");
        char c = text_[pos_];
        if (c == quote && (!triple || (at(1) == quote && at(2) == quote))) {
            pos_ += triple ? 3 : 1;
            return;
        }
        ++pos_;
        if (c == '\\') {
            if (pos_ >= text_.size()) fail(token, "unterminated string");
            scanEscape(token.value);
        } else if (c == '\n') {
            if (!triple) fail(token, "unterminated string (a line break inside a one-line string)");
            newline();
            token.value += c;
        } else {
            token.value += c;
        }
    }
}

void Lexer::scanAsset(Token& token) {
    token.kind = TokenKind::Asset;
    if (text_.substr(pos_, 3) != "@@@") {
        ++pos_;
        std::size_t start = pos_;
        while (pos_ < text_.size() && text_[pos_] != '@' && text_[pos_] != '\n') ++pos_;
        if (current() != '@') fail(token, "unterminated asset path");
        token.value.assign(text_.substr(start, pos_ - start));
        ++pos_;
        return;
    }
    // @@@...@@@: ends at the last three of the first run of three or more '@'s; \@@@ is an
    // escaped delimiter.
    pos_ += 3;
    while (true) {
        if (pos_ >= text_.size() || current() == '\n') fail(token, "unterminated asset path");
        if (current() == '\\' && text_.substr(pos_ + 1, 3) == "@@@") {
            token.value += "@@@";
            pos_ += 4;
        } else if (text_.substr(pos_, 3) == "@@@") {
            std::size_t run = 0;
            while (at(run) == '@') ++run;
            token.value.append(run - 3, '@');
            pos_ += run;
            return;
        } else {
            token.value += text_[pos_++];
        }
    }
}

void Lexer::scanPath(Token& token) {
    token.kind = TokenKind::Path;
    ++pos_;
    std::size_t start = pos_;
    while (pos_ < text_.size() && text_[pos_] != '>' && text_[pos_] != '\n') ++pos_;
    if (current() != '>') fail(token, "unterminated path (missing '>')");
    token.value.assign(text_.substr(start, pos_ - start));
    ++pos_;
}

}  // namespace fluence::usd::detail
