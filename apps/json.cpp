#include "apps/json.h"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace fluence::app {

namespace {

class Reader {
public:
    explicit Reader(const std::string& text) : s_(text) {}

    JsonValue document() {
        JsonValue v = value();
        skipSpace();
        if (i_ != s_.size()) fail("the end of the document");
        return v;
    }

private:
    [[noreturn]] void fail(const std::string& expected) const {
        throw JsonError("JSON: expected " + expected + " at byte " + std::to_string(i_));
    }
    void skipSpace() {
        while (i_ < s_.size() && (s_[i_] == ' ' || s_[i_] == '\t' || s_[i_] == '\n' || s_[i_] == '\r')) ++i_;
    }
    bool take(char c) {
        skipSpace();
        if (i_ < s_.size() && s_[i_] == c) {
            ++i_;
            return true;
        }
        return false;
    }
    void expect(char c) {
        if (!take(c)) fail(std::string("'") + c + "'");
    }
    bool word(const char* w) {
        const std::string_view view(w);
        if (s_.compare(i_, view.size(), view) != 0) return false;
        i_ += view.size();
        return true;
    }

    JsonValue value() {
        if (++depth_ > 200) fail("less nesting");
        skipSpace();
        if (i_ >= s_.size()) fail("a value");
        JsonValue v;
        const char c = s_[i_];
        if (c == '{') {
            ++i_;
            JsonValue::Object members;
            if (!take('}')) {
                do {
                    skipSpace();
                    std::string key = string();
                    expect(':');
                    members.emplace_back(std::move(key), value());
                } while (take(','));
                expect('}');
            }
            v = JsonValue(std::move(members));
        } else if (c == '[') {
            ++i_;
            JsonValue::Array items;
            if (!take(']')) {
                do items.push_back(value());
                while (take(','));
                expect(']');
            }
            v = JsonValue(std::move(items));
        } else if (c == '"') {
            v = JsonValue(string());
        } else if (word("true")) {
            v = JsonValue(true);
        } else if (word("false")) {
            v = JsonValue(false);
        } else if (word("null")) {
            v = JsonValue();
        } else {
            v = JsonValue(number());
        }
        --depth_;
        return v;
    }

    double number() {
        const std::size_t start = i_;
        auto digits = [&] {
            const std::size_t from = i_;
            while (i_ < s_.size() && s_[i_] >= '0' && s_[i_] <= '9') ++i_;
            return i_ > from;
        };
        if (i_ < s_.size() && s_[i_] == '-') ++i_;
        if (!digits()) fail("a value");
        if (i_ < s_.size() && s_[i_] == '.' && (++i_, !digits())) fail("digits after '.'");
        if (i_ < s_.size() && (s_[i_] == 'e' || s_[i_] == 'E')) {
            ++i_;
            if (i_ < s_.size() && (s_[i_] == '+' || s_[i_] == '-')) ++i_;
            if (!digits()) fail("an exponent");
        }
        double v = 0.0;
        std::from_chars(s_.data() + start, s_.data() + i_, v);
        return v;
    }

    unsigned hex4() {
        if (i_ + 4 > s_.size()) fail("four hex digits");
        unsigned v = 0;
        auto [end, error] = std::from_chars(s_.data() + i_, s_.data() + i_ + 4, v, 16);
        if (error != std::errc() || end != s_.data() + i_ + 4) fail("four hex digits");
        i_ += 4;
        return v;
    }

    void appendUtf8(std::string& out, unsigned cp) {
        if (cp < 0x80) {
            out += char(cp);
        } else if (cp < 0x800) {
            out += char(0xC0 | (cp >> 6));
            out += char(0x80 | (cp & 0x3F));
        } else if (cp < 0x10000) {
            out += char(0xE0 | (cp >> 12));
            out += char(0x80 | ((cp >> 6) & 0x3F));
            out += char(0x80 | (cp & 0x3F));
        } else {
            out += char(0xF0 | (cp >> 18));
            out += char(0x80 | ((cp >> 12) & 0x3F));
            out += char(0x80 | ((cp >> 6) & 0x3F));
            out += char(0x80 | (cp & 0x3F));
        }
    }

    std::string string() {
        if (i_ >= s_.size() || s_[i_] != '"') fail("a string");
        ++i_;
        std::string out;
        while (true) {
            if (i_ >= s_.size()) fail("the closing '\"'");
            const unsigned char c = static_cast<unsigned char>(s_[i_++]);
            if (c == '"') return out;
            if (c < 0x20) fail("no control character in a string");
            if (c != '\\') {
                out += char(c);
                continue;
            }
            if (i_ >= s_.size()) fail("an escape");
            switch (s_[i_++]) {
                case '"': out += '"'; break;
                case '\\': out += '\\'; break;
                case '/': out += '/'; break;
                case 'b': out += '\b'; break;
                case 'f': out += '\f'; break;
                case 'n': out += '\n'; break;
                case 'r': out += '\r'; break;
                case 't': out += '\t'; break;
                case 'u': {
                    unsigned cp = hex4();
                    if (cp >= 0xD800 && cp < 0xDC00) {  // a surrogate pair
                        if (!word("\\u")) fail("a low surrogate");
                        const unsigned low = hex4();
                        if (low < 0xDC00 || low >= 0xE000) fail("a low surrogate");
                        cp = 0x10000 + ((cp - 0xD800) << 10) + (low - 0xDC00);
                    }
                    appendUtf8(out, cp);
                    break;
                }
                default: --i_; fail("a valid escape");
            }
        }
    }

    const std::string& s_;
    std::size_t i_ = 0;
    int depth_ = 0;
};

[[noreturn]] void wrongType(const std::string& what, const char* type) { throw JsonError(what + " must be " + type); }

}  // namespace

bool JsonValue::asBool(const std::string& what) const {
    if (const bool* b = std::get_if<bool>(&value_)) return *b;
    wrongType(what, "true or false");
}

double JsonValue::asNumber(const std::string& what) const {
    if (const double* d = std::get_if<double>(&value_)) return *d;
    wrongType(what, "a number");
}

int JsonValue::asInt(const std::string& what) const {
    const double d = asNumber(what);
    if (d != std::floor(d) || std::abs(d) > 2147483647.0) wrongType(what, "an integer");
    return int(d);
}

const std::string& JsonValue::asString(const std::string& what) const {
    if (const std::string* s = std::get_if<std::string>(&value_)) return *s;
    wrongType(what, "a string");
}

const JsonValue::Array& JsonValue::asArray(const std::string& what) const {
    if (const auto* a = std::get_if<std::shared_ptr<Array>>(&value_)) return **a;
    wrongType(what, "an array");
}

const JsonValue* JsonValue::find(const std::string& key) const {
    if (const auto* o = std::get_if<std::shared_ptr<Object>>(&value_))
        for (const auto& [name, member] : **o)
            if (name == key) return &member;
    return nullptr;
}

const JsonValue& JsonValue::at(const std::string& key, const std::string& what) const {
    if (!isObject()) wrongType(what, "an object");
    if (const JsonValue* member = find(key)) return *member;
    throw JsonError(what + " has no \"" + key + "\"");
}

JsonValue parseJson(const std::string& text) { return Reader(text).document(); }

std::string jsonQuoted(const std::string& text) {
    std::string out = "\"";
    for (unsigned char c : text) {
        if (c == '"' || c == '\\') {
            out += '\\';
            out += char(c);
        } else if (c < 0x20) {
            char escape[8];
            std::snprintf(escape, sizeof escape, "\\u%04x", c);
            out += escape;
        } else {
            out += char(c);
        }
    }
    return out + "\"";
}

std::string jsonNumber(double v) {
    if (!std::isfinite(v)) return "null";
    char buffer[32];
    auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, v);
    return error == std::errc() ? std::string(buffer, end) : "null";
}

}  // namespace fluence::app
