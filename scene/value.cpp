#include "scene/value.h"

#include <charconv>
#include <cmath>

namespace fluence::usd {

namespace {

constexpr std::size_t kShownElements = 8;  // toString elides arrays past this many elements

std::string formatNumber(double x) {
    if (std::isnan(x)) return "nan";
    if (std::isinf(x)) return x < 0 ? "-inf" : "inf";
    char buffer[32];
    auto result = std::to_chars(buffer, buffer + sizeof buffer, x);
    return std::string(buffer, result.ptr);
}

std::string quote(const std::string& s) {
    std::string out = "\"";
    for (char c : s) {
        switch (c) {
            case '"': out += "\\\""; break;
            case '\\': out += "\\\\"; break;
            case '\n': out += "\\n"; break;
            case '\t': out += "\\t"; break;
            default: out += c;
        }
    }
    return out + "\"";
}

// One Numeric element: "1", "(1, 2, 3)", or rows "((1, 0), (0, 1))" for square matrix types.
std::string formatNumericElement(const Value& value, std::size_t element) {
    const double* first = value.numbers.data() + element * value.components;
    int n = value.components;
    if (n == 1) return formatNumber(first[0]);
    int rows = value.typeName.find("matrix") == 0 || value.typeName.find("frame") == 0
                   ? static_cast<int>(std::lround(std::sqrt(n)))
                   : 1;
    if (rows * rows != n) rows = 1;
    int columns = n / rows;
    std::string out = rows > 1 ? "(" : "";
    for (int r = 0; r < rows; ++r) {
        if (r) out += ", ";
        out += "(";
        for (int c = 0; c < columns; ++c) {
            if (c) out += ", ";
            out += formatNumber(first[r * columns + c]);
        }
        out += ")";
    }
    return rows > 1 ? out + ")" : out;
}

std::string formatElement(const Value& value, std::size_t element) {
    switch (value.kind) {
        case ValueKind::Numeric: return formatNumericElement(value, element);
        case ValueKind::String:
        case ValueKind::Token: return quote(value.strings[element]);
        case ValueKind::Asset: return "@" + value.strings[element] + "@";
        case ValueKind::Path: return "<" + value.strings[element] + ">";
        case ValueKind::List: return value.items[element].toString();
        default: return "";
    }
}

std::string formatReference(const Value& value) {
    std::string out;
    if (!value.strings.empty() && !value.strings[0].empty()) out += "@" + value.strings[0] + "@";
    if (value.strings.size() > 1 && !value.strings[1].empty()) out += "<" + value.strings[1] + ">";
    if (value.numbers.size() == 2) {
        out += " (offset = " + formatNumber(value.numbers[0]) + "; scale = " + formatNumber(value.numbers[1]) + ")";
    }
    return out;
}

std::string formatDictionary(const Dictionary& dictionary) {
    std::string out = "{";
    for (const auto& [key, entry] : dictionary) {
        out += out.size() > 1 ? ", " : " ";
        if (!entry.typeName.empty()) out += entry.typeName + " ";
        out += key + " = " + entry.toString();
    }
    return out + (dictionary.empty() ? "}" : " }");
}

}  // namespace

std::size_t Value::size() const {
    switch (kind) {
        case ValueKind::Blocked: return 0;
        case ValueKind::Numeric: return components > 0 ? numbers.size() / components : 0;
        case ValueKind::List: return items.size();
        case ValueKind::Dictionary: return dictionary ? dictionary->size() : 0;
        case ValueKind::Reference: return 1;
        default: return strings.size();
    }
}

std::optional<double> Value::asDouble() const {
    if (kind != ValueKind::Numeric || numbers.empty()) return std::nullopt;
    return numbers.front();
}

std::optional<std::string> Value::asString() const {
    if (!isStringLike() || strings.empty()) return std::nullopt;
    return strings.front();
}

const Value* Value::find(const std::string& key) const {
    if (kind != ValueKind::Dictionary || !dictionary) return nullptr;
    for (const auto& [name, entry] : *dictionary) {
        if (name == key) return &entry;
    }
    return nullptr;
}

std::string Value::toString() const {
    switch (kind) {
        case ValueKind::Blocked: return "None";
        case ValueKind::Reference: return formatReference(*this);
        case ValueKind::Dictionary: return dictionary ? formatDictionary(*dictionary) : "{}";
        default: break;
    }
    std::size_t count = size();
    if (!isArray && kind != ValueKind::List) return count ? formatElement(*this, 0) : "";
    bool tuple = kind == ValueKind::List && !isArray;
    std::string out = tuple ? "(" : "[";
    for (std::size_t i = 0; i < count && i < kShownElements; ++i) {
        if (i) out += ", ";
        out += formatElement(*this, i);
    }
    if (count > kShownElements) out += ", ... (" + std::to_string(count) + " elements)";
    return out + (tuple ? ")" : "]");
}

Value Value::numeric(std::string typeName, std::vector<double> numbers, int components, bool isArray) {
    Value value;
    value.typeName = std::move(typeName);
    value.kind = ValueKind::Numeric;
    value.isArray = isArray;
    value.components = components;
    value.numbers = std::move(numbers);
    return value;
}

Value Value::string(std::string typeName, ValueKind kind, std::vector<std::string> strings, bool isArray) {
    Value value;
    value.typeName = std::move(typeName);
    value.kind = kind;
    value.isArray = isArray;
    value.strings = std::move(strings);
    return value;
}

Value Value::list(std::vector<Value> items) {
    Value value;
    value.kind = ValueKind::List;
    value.isArray = true;
    value.items = std::move(items);
    return value;
}

}  // namespace fluence::usd
