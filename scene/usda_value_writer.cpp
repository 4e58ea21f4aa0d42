#include "scene/usda_value_writer.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "scene/usda_names.h"
#include "scene/usda_value_types.h"

namespace fluence::usd::detail {

namespace {

enum class NumberForm { Double, Float, Half, Integer, Bool };

// How numbers of a type are written. Precision comes from the type's name: USD names half types
// with an 'h' and float types with an 'f' (legacy: "Float"); everything else is a double.
NumberForm numberFormOf(std::string_view baseType) {
    const ValueType* type = findValueType(baseType);
    if (!type) return NumberForm::Double;
    if (type->element == ElementKind::Bool) return NumberForm::Bool;
    if (type->element == ElementKind::Integer) return NumberForm::Integer;
    if (type->element != ElementKind::Float) return NumberForm::Double;
    if (baseType.starts_with("half") || baseType.ends_with('h')) return NumberForm::Half;
    if (baseType.starts_with("float") || baseType.ends_with('f') || baseType.ends_with("Float"))
        return NumberForm::Float;
    return NumberForm::Double;
}

std::string_view baseTypeOf(std::string_view typeName) {
    if (typeName.ends_with("[]")) typeName.remove_suffix(2);
    return typeName;
}

template <class... Format>
std::string toChars(auto number, Format... format) {
    std::array<char, 64> buffer{};
    auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), number, format...);
    return std::string(buffer.data(), result.ptr);
}

// The shortest digits that read back to `number` (a float or a double), laid out as USD lays them
// out (TfStringify: double-conversion's ToShortest with decimal notation from 1e-6 up to 1e15,
// else d.ddde-7 / d.ddde15): 0.000001, 100000, 1e-7, 1e15.
template <class Number>
std::string shortestText(Number number) {
    if (std::isnan(number)) return "nan";
    if (std::isinf(number)) return number < 0 ? "-inf" : "inf";
    const std::string scientific = toChars(number, std::chars_format::scientific);  // "-1.25e-07"
    const std::size_t e = scientific.find('e');
    const bool negative = scientific.front() == '-';
    std::string digits = scientific.substr(negative ? 1 : 0, e - (negative ? 1 : 0));
    std::erase(digits, '.');
    const int exponent = std::stoi(scientific.substr(e + 1));
    const int point = exponent + 1;  // the value is 0.digits * 10^point
    const int count = static_cast<int>(digits.size());
    std::string text = negative ? "-" : "";
    if (point > -6 && point <= 15) {
        if (point <= 0)
            text += "0." + std::string(static_cast<std::size_t>(-point), '0') + digits;
        else if (point >= count)
            text += digits + std::string(static_cast<std::size_t>(point - count), '0');
        else
            text += digits.substr(0, static_cast<std::size_t>(point)) + "." +
                    digits.substr(static_cast<std::size_t>(point));
    } else {
        text += digits.substr(0, 1);
        if (count > 1) text += "." + digits.substr(1);
        text += "e" + std::to_string(exponent);
    }
    return text;
}

bool isFloat(double number) {
    return std::isfinite(number) && std::fabs(number) <= std::numeric_limits<float>::max() &&
           static_cast<double>(static_cast<float>(number)) == number;
}

// Exactly a 16-bit half: at most 11 significant bits, a multiple of 2^-24 (the smallest
// subnormal), at most 65504 in magnitude.
bool isHalf(double number) {
    if (!(std::fabs(number) <= 65504.0)) return false;
    if (number == 0.0) return true;
    int exponent = 0;
    std::frexp(number, &exponent);
    double significand = std::ldexp(number, 11 - exponent), units = std::ldexp(number, 24);
    return significand == std::trunc(significand) && units == std::trunc(units);
}

std::string formatNumber(double number, NumberForm form) {
    switch (form) {
        case NumberForm::Bool: return number != 0.0 ? "1" : "0";
        case NumberForm::Integer:
            return std::isfinite(number) ? toChars(number, std::chars_format::fixed) : shortestText(number);
        case NumberForm::Float:
            return isFloat(number) ? shortestText(static_cast<float>(number)) : shortestText(number);
        case NumberForm::Half:
            // USD streams a half as its float with the stream's default 6 significant digits.
            return isHalf(number) ? toChars(static_cast<float>(number), std::chars_format::general, 6)
                                  : shortestText(number);
        case NumberForm::Double: break;
    }
    return shortestText(number);
}

void pad(std::string& out, int indent) { out.append(static_cast<std::size_t>(indent) * 4, ' '); }

// One element of `components` numbers starting at numbers[first]: a scalar, a tuple, or (for
// rowSize > 0) a tuple of rows.
void writeNumericElement(std::string& out, const Value& value, std::size_t first, int rowSize, const auto& format) {
    const int components = std::max(value.components, 1);
    if (components == 1) {
        out += format(value.numbers[first]);
        return;
    }
    auto writeTuple = [&](std::size_t start, int count) {
        out += '(';
        for (int i = 0; i < count; ++i) {
            if (i) out += ", ";
            out += format(value.numbers[start + static_cast<std::size_t>(i)]);
        }
        out += ')';
    };
    if (rowSize > 0 && rowSize * rowSize == components) {
        out += '(';
        for (int row = 0; row < rowSize; ++row) {
            if (row) out += ", ";
            writeTuple(first + static_cast<std::size_t>(row * rowSize), rowSize);
        }
        out += ')';
    } else {
        writeTuple(first, components);
    }
}

void writeNumbers(std::string& out, const Value& value, int rowSize, const auto& format) {
    const std::size_t components = static_cast<std::size_t>(std::max(value.components, 1));
    const std::size_t count = value.numbers.size() / components;
    if (!value.isArray) {
        if (count == 0) throw std::invalid_argument("a '" + value.typeName + "' value without numbers");
        writeNumericElement(out, value, 0, rowSize, format);
        return;
    }
    out += '[';
    for (std::size_t i = 0; i < count; ++i) {
        if (i) out += ", ";
        writeNumericElement(out, value, i * components, rowSize, format);
    }
    out += ']';
}

// Elements of a string-like value, one after another: a scalar, or a [...] list when isArray.
void writeStrings(std::string& out, const Value& value, const auto& format) {
    if (!value.isArray) {
        if (value.strings.empty()) throw std::invalid_argument("a '" + value.typeName + "' value without text");
        out += format(value.strings.front());
        return;
    }
    out += '[';
    for (std::size_t i = 0; i < value.strings.size(); ++i) {
        if (i) out += ", ";
        out += format(value.strings[i]);
    }
    out += ']';
}

std::string pathText(const std::string& path) { return "<" + path + ">"; }

// Words the reader takes for something else than a token.
bool isReservedWord(std::string_view word) {
    for (std::string_view reserved : {"None", "true", "false", "True", "False", "inf", "nan"})
        if (word == reserved) return true;
    return false;
}

// A token the lexer reads back as one identifier: names joined by ':' or '::'.
bool isBareWord(std::string_view word) {
    if (word.empty() || isReservedWord(word)) return false;
    std::size_t start = 0;
    while (true) {
        std::size_t colon = word.find(':', start);
        std::string_view part = word.substr(start, colon == std::string_view::npos ? colon : colon - start);
        if (part.empty() || !identifierProblem(part).empty()) return false;
        if (colon == std::string_view::npos) return true;
        start = colon + (colon + 1 < word.size() && word[colon + 1] == ':' ? 2 : 1);
    }
}

enum class TokenStyle { Auto, Quoted, Bare };

void writeGeneric(std::string& out, const Value& value, int indent, TokenStyle tokens, bool boolWords);

// A [...] or (...) list of untyped items; one item per line when they are references or
// dictionaries, as USD writes reference lists.
void writeList(std::string& out, const Value& list, int indent) {
    const char open = list.isArray ? '[' : '(', close = list.isArray ? ']' : ')';
    bool itemPerLine = std::any_of(list.items.begin(), list.items.end(), [](const Value& item) {
        return item.kind == ValueKind::Reference || item.kind == ValueKind::Dictionary;
    });
    out += open;
    if (itemPerLine && !list.items.empty()) {
        out += '\n';
        for (std::size_t i = 0; i < list.items.size(); ++i) {
            pad(out, indent + 1);
            writeGeneric(out, list.items[i], indent + 1, TokenStyle::Auto, false);
            out += i + 1 < list.items.size() ? ",\n" : "\n";
        }
        pad(out, indent);
    } else {
        for (std::size_t i = 0; i < list.items.size(); ++i) {
            if (i) out += ", ";
            writeGeneric(out, list.items[i], indent, TokenStyle::Auto, false);
        }
    }
    out += close;
}

void writeGeneric(std::string& out, const Value& value, int indent, TokenStyle tokens, bool boolWords) {
    const std::string_view baseType = baseTypeOf(value.typeName);
    switch (value.kind) {
        case ValueKind::Blocked: out += "None"; return;
        case ValueKind::Numeric: {
            const NumberForm form = numberFormOf(baseType);
            if (boolWords || form == NumberForm::Bool) {
                writeNumbers(out, value, 0, [](double x) { return std::string(x != 0.0 ? "true" : "false"); });
            } else {
                writeNumbers(out, value, 0, [form](double x) { return formatNumber(x, form); });
            }
            return;
        }
        case ValueKind::String: writeStrings(out, value, quoteString); return;
        case ValueKind::Token: {
            // Bare identifiers read back as untyped tokens; a token of a declared type is quoted.
            const bool untyped = baseType.empty() || !findValueType(baseType);
            writeStrings(out, value, [&](const std::string& word) {
                if (tokens == TokenStyle::Bare && (word.empty() || isBareWord(word))) return word;
                if (tokens == TokenStyle::Auto && untyped && isBareWord(word)) return word;
                return quoteString(word);
            });
            return;
        }
        case ValueKind::Asset:
            writeStrings(out, value, [](const std::string& path) { return quoteAssetPath(path); });
            return;
        case ValueKind::Path: writeStrings(out, value, pathText); return;
        case ValueKind::Reference: writeReference(out, value, indent); return;
        case ValueKind::List: writeList(out, value, indent); return;
        case ValueKind::Dictionary: writeDictionary(out, value, indent); return;
    }
}

// The type a dictionary entry is declared with: its own, or one that holds it.
std::string entryTypeName(const Value& value) {
    if (!value.typeName.empty()) return value.typeName;
    std::string base;
    switch (value.kind) {
        case ValueKind::Dictionary: return "dictionary";
        case ValueKind::Blocked:
        case ValueKind::String: base = "string"; break;
        case ValueKind::Token: base = "token"; break;
        case ValueKind::Asset: base = "asset"; break;
        case ValueKind::Numeric:
            if (value.components == 1)
                base = "double";
            else if (value.components >= 2 && value.components <= 4)
                base = "double" + std::to_string(value.components);
            else if (value.components == 9)
                base = "matrix3d";
            else if (value.components == 16)
                base = "matrix4d";
            break;
        default: break;
    }
    if (base.empty())
        throw std::invalid_argument("a dictionary entry holds a value no USD type can hold: " + value.toString());
    return value.isArray ? base + "[]" : base;
}

// A string map ({"a": "b"}) or path map ({<a>: <b>}): untyped String or Path entries only.
bool isMap(const Value& dictionary) {
    if (!dictionary.typeName.empty() || !dictionary.dictionary || dictionary.dictionary->empty()) return false;
    const ValueKind kind = dictionary.dictionary->front().second.kind;
    return (kind == ValueKind::String || kind == ValueKind::Path) &&
           std::all_of(dictionary.dictionary->begin(), dictionary.dictionary->end(), [kind](const auto& entry) {
               const Value& v = entry.second;
               return v.kind == kind && v.typeName.empty() && !v.isArray && v.strings.size() == 1;
           });
}

// The layer offset and customData of a reference, "(offset = 1; scale = 2)", or nothing.
void writeArcFields(std::string& out, const Value& reference, int indent) {
    std::vector<std::string> fields;
    if (reference.numbers.size() >= 2) {
        const double offset = reference.numbers[0], scale = reference.numbers[1];
        const bool writeScale = !(scale == 1.0);
        // An offset is written unless it is +0 and the scale says the offset was authored.
        if (!(offset == 0.0 && !std::signbit(offset)) || !writeScale)
            fields.push_back("offset = " + shortestText(offset));
        if (writeScale) fields.push_back("scale = " + shortestText(scale));
    }
    if (reference.dictionary) {
        Value customData;
        customData.typeName = "dictionary";
        customData.kind = ValueKind::Dictionary;
        customData.dictionary = reference.dictionary;
        std::string text = "customData = ";
        writeDictionary(text, customData, indent);
        fields.push_back(std::move(text));
    }
    if (fields.empty()) return;
    out += " (";
    for (std::size_t i = 0; i < fields.size(); ++i) out += (i ? "; " : "") + fields[i];
    out += ')';
}

}  // namespace

std::string quoteString(std::string_view text) {
    const char quote =
        text.find('"') != std::string_view::npos && text.find('\'') == std::string_view::npos ? '\'' : '"';
    const bool triple = text.find('\n') != std::string_view::npos;
    std::string out(triple ? 3 : 1, quote);
    static const char* hex = "0123456789abcdef";
    for (std::size_t i = 0; i < text.size(); ++i) {
        const unsigned char c = static_cast<unsigned char>(text[i]);
        // A well-formed UTF-8 multi-byte sequence is kept as is.
        int length = (c & 0xE0) == 0xC0 ? 2 : (c & 0xF0) == 0xE0 ? 3 : (c & 0xF8) == 0xF0 ? 4 : 0;
        bool multiByte = length > 0 && i + static_cast<std::size_t>(length) <= text.size();
        for (int k = 1; multiByte && k < length; ++k)
            multiByte = (static_cast<unsigned char>(text[i + static_cast<std::size_t>(k)]) & 0xC0) == 0x80;
        if (multiByte) {
            out.append(text.substr(i, static_cast<std::size_t>(length)));
            i += static_cast<std::size_t>(length) - 1;
            continue;
        }
        switch (c) {
            case '\n': out += triple ? "\n" : "\\n"; break;
            case '\r': out += "\\r"; break;
            case '\t': out += "\\t"; break;
            case '\\': out += "\\\\"; break;
            default:
                if (c == static_cast<unsigned char>(quote)) {
                    out += '\\';
                    out += quote;
                } else if (c < 32 || c > 126) {
                    out += "\\x";
                    out += hex[c >> 4];
                    out += hex[c & 15];
                } else {
                    out += static_cast<char>(c);
                }
        }
    }
    out.append(triple ? 3 : 1, quote);
    return out;
}

std::string quoteAssetPath(std::string_view path) {
    if (path.find('@') == std::string_view::npos) {
        std::string out = "@";
        out.append(path);
        return out += '@';
    }
    std::string out = "@@@";
    for (std::size_t i = 0; i < path.size(); ++i) {
        if (path.substr(i, 3) == "@@@") {
            out += "\\@@@";
            i += 2;
        } else {
            out += path[i];
        }
    }
    return out + "@@@";
}

std::string formatNumber(double number, std::string_view baseType) {
    return formatNumber(number, numberFormOf(baseType));
}

void writeTypedValue(std::string& out, const Value& value, std::string_view typeName, int indent) {
    const std::string_view baseType = baseTypeOf(typeName);
    const ValueType* type = findValueType(baseType);
    if (value.isBlocked()) {
        out += "None";
    } else if (type && value.isNumeric()) {
        const NumberForm form = numberFormOf(baseType);
        writeNumbers(out, value, type->rank == 2 ? type->size : 0, [form](double x) { return formatNumber(x, form); });
    } else if (type && value.isStringLike() && value.kind != ValueKind::Path) {
        if (type->element == ElementKind::Asset)
            writeStrings(out, value, [](const std::string& path) { return quoteAssetPath(path); });
        else
            writeStrings(out, value, quoteString);
    } else {
        // Unknown types are read as untyped values, and a path stands for a value of any type:
        // written by their shape.
        writeGeneric(out, value, indent, TokenStyle::Auto, false);
    }
}

void writeMetadataValue(std::string& out, const Value& value, std::string_view key, int indent) {
    const bool boolField = key == "active" || key == "hidden" || key == "instanceable" || key == "noLoadHint";
    TokenStyle tokens = TokenStyle::Auto;
    if (key == "kind" || key == "colorSpace") tokens = TokenStyle::Quoted;
    if (key == "permission" || key == "displayUnit" || key == "symmetryFunction") tokens = TokenStyle::Bare;
    writeGeneric(out, value, indent, tokens, boolField && value.isNumeric() && !value.isArray);
}

void writeDictionary(std::string& out, const Value& dictionary, int indent) {
    out += "{\n";
    if (isMap(dictionary)) {
        const bool paths = dictionary.dictionary->front().second.kind == ValueKind::Path;
        for (const auto& [key, value] : *dictionary.dictionary) {
            pad(out, indent + 1);
            out += (paths ? pathText(key) : quoteString(key)) + ": ";
            out += (paths ? pathText(value.strings.front()) : quoteString(value.strings.front())) + ",\n";
        }
    } else if (dictionary.dictionary) {
        for (const auto& [key, value] : *dictionary.dictionary) {
            const std::string typeName = entryTypeName(value);
            pad(out, indent + 1);
            out += typeName + " " + (identifierProblem(key).empty() ? key : quoteString(key)) + " = ";
            if (typeName == "dictionary" && value.kind == ValueKind::Dictionary)
                writeDictionary(out, value, indent + 1);
            else
                writeTypedValue(out, value, typeName, indent + 1);
            out += '\n';
        }
    }
    pad(out, indent);
    out += '}';
}

void writeReference(std::string& out, const Value& reference, int indent) {
    const std::string asset = reference.strings.empty() ? "" : reference.strings[0];
    const std::string primPath = reference.strings.size() > 1 ? reference.strings[1] : "";
    if (!asset.empty()) {
        out += quoteAssetPath(asset);
        if (!primPath.empty()) out += pathText(primPath);
    } else {
        out += pathText(primPath);  // internal: </Prim>, or <> for the default prim
    }
    writeArcFields(out, reference, indent);
}

}  // namespace fluence::usd::detail
