// JSON for the files Fluence writes and reads back itself (the farm plan, task records): a value
// type, a strict reader (RFC 8259; numbers as double; objects keep their key order) and the two
// writing helpers every writer here uses. Not a general-purpose library: no streaming, no
// comments, documents are small.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace fluence::app {

// A document that is not JSON; the message gives the byte offset and what was expected.
class JsonError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class JsonValue {
public:
    using Array = std::vector<JsonValue>;
    using Object = std::vector<std::pair<std::string, JsonValue>>;

    JsonValue() = default;  // null
    explicit JsonValue(bool b) : value_(b) {}
    explicit JsonValue(double d) : value_(d) {}
    explicit JsonValue(std::string s) : value_(std::move(s)) {}
    explicit JsonValue(Array a) : value_(std::make_shared<Array>(std::move(a))) {}
    explicit JsonValue(Object o) : value_(std::make_shared<Object>(std::move(o))) {}

    bool isNull() const { return std::holds_alternative<std::monostate>(value_); }
    bool isNumber() const { return std::holds_alternative<double>(value_); }
    bool isString() const { return std::holds_alternative<std::string>(value_); }
    bool isArray() const { return std::holds_alternative<std::shared_ptr<Array>>(value_); }
    bool isObject() const { return std::holds_alternative<std::shared_ptr<Object>>(value_); }

    // The typed accessors throw JsonError naming `what` when the value has another type.
    bool asBool(const std::string& what) const;
    double asNumber(const std::string& what) const;
    int asInt(const std::string& what) const;  // a number that is an integer
    const std::string& asString(const std::string& what) const;
    const Array& asArray(const std::string& what) const;
    // The member `key` of an object; throws JsonError naming `what.key` when it is missing.
    const JsonValue& at(const std::string& key, const std::string& what) const;
    // The member `key`, or nullptr when the object has none.
    const JsonValue* find(const std::string& key) const;

private:
    std::variant<std::monostate, bool, double, std::string, std::shared_ptr<Array>, std::shared_ptr<Object>> value_;
};

// Parses a whole document. Throws JsonError.
JsonValue parseJson(const std::string& text);

// `text` as a JSON string literal, quotes included.
std::string jsonQuoted(const std::string& text);
// `v` as a JSON number in its shortest exact form; null when it is not finite.
std::string jsonNumber(double v);

}  // namespace fluence::app
