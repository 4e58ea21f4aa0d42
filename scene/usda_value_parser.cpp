#include "scene/usda_value_parser.h"

#include <cctype>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <unordered_map>
#include <utility>

namespace fluence::usd::detail {

namespace {

std::string location(const Token& token) { return std::to_string(token.line) + ":" + std::to_string(token.column); }

std::string expectedElement(const ValueType& type) {
    switch (type.element) {
        case ElementKind::Bool: return "a bool (a number, true, false, yes or no)";
        case ElementKind::Integer: return "an integer";
        case ElementKind::Float: return "a number";
        case ElementKind::Asset: return "an asset path @...@ or a quoted string";
        default: return "a quoted string";
    }
}

ValueKind stringKindOf(ElementKind element) {
    switch (element) {
        case ElementKind::Token: return ValueKind::Token;
        case ElementKind::Asset: return ValueKind::Asset;
        default: return ValueKind::String;
    }
}

// The words a float element may be written as, bare or quoted: inf, -inf and nan (bare, -inf is
// a number token).
std::optional<double> floatFromWord(std::string_view word) {
    if (word == "inf") return std::numeric_limits<double>::infinity();
    if (word == "-inf") return -std::numeric_limits<double>::infinity();
    if (word == "nan") return std::numeric_limits<double>::quiet_NaN();
    return std::nullopt;
}

// The elements of `type` that the lexer's bulk path reads: numbers and tuples of numbers
// (matrices and bools take the token path).
std::optional<NumericShape> plainShape(const ValueType& type) {
    if (type.rank > 1 || type.element == ElementKind::Bool) return std::nullopt;
    NumericShape shape;
    shape.tupleSize = type.rank == 1 ? type.size : 0;
    shape.integers = type.element == ElementKind::Integer;
    shape.min = type.min;
    shape.max = type.max;
    return shape;
}

// One Value from the items of a generic '[...]' list: a flat typed array when the items agree.
Value flattenList(std::vector<Value> items) {
    if (!items.empty()) {
        const Value& first = items.front();
        bool sameNumeric = true, sameStrings = true;
        for (const Value& item : items) {
            sameNumeric =
                sameNumeric && item.kind == ValueKind::Numeric && !item.isArray && item.components == first.components;
            sameStrings = sameStrings && item.kind == first.kind && item.isStringLike() && !item.isArray &&
                          item.strings.size() == 1;
        }
        if (sameNumeric) {
            std::vector<double> numbers;
            numbers.reserve(items.size() * static_cast<std::size_t>(first.components));
            for (const Value& item : items) {
                numbers.insert(numbers.end(), item.numbers.begin(), item.numbers.end());
            }
            return Value::numeric("", std::move(numbers), first.components, true);
        }
        if (sameStrings) {
            std::vector<std::string> strings;
            strings.reserve(items.size());
            for (Value& item : items) strings.push_back(std::move(item.strings.front()));
            return Value::string("", first.kind, std::move(strings), true);
        }
    }
    return Value::list(std::move(items));
}

}  // namespace

std::optional<bool> boolFromToken(const Token& token) {
    if (token.kind == TokenKind::Number) return token.number != 0.0;
    if (token.kind != TokenKind::Identifier && token.kind != TokenKind::String) return std::nullopt;
    std::string word(token.kind == TokenKind::String ? std::string_view(token.value) : token.text);
    for (char& c : word) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (word == "true" || word == "yes" || word == "1") return true;
    if (word == "false" || word == "no" || word == "0") return false;
    return std::nullopt;
}

Value ValueParser::parseTyped(std::string_view baseType, bool isArray) {
    std::string typeName(baseType);
    if (isArray) typeName += "[]";
    if (lexer_.peek().isWord("None")) {
        lexer_.skip();
        Value blocked;
        blocked.typeName = std::move(typeName);
        blocked.isArray = isArray;
        return blocked;
    }
    if (lexer_.peek().kind == TokenKind::Path) {
        // Sdf's typed_value takes a path for a value of any type (a token or string attribute
        // holding the path of an output, say); it is kept as a path under the declared type.
        return Value::string(std::move(typeName), ValueKind::Path, {lexer_.take().value}, false);
    }
    const ValueType* type = findValueType(baseType);
    if (!type) {
        // Sdf keeps the text of a value of an unknown type, which must still be a typed_value: no
        // dictionary.
        if (lexer_.peek().is('{'))
            lexer_.fail(lexer_.peek(), "a value of type '" + typeName + "' cannot be a dictionary {...}" +
                                           (baseType == "dictionary" ? " ('dictionary' is a type of dictionary "
                                                                       "entries and metadata, not of attributes)"
                                                                     : ""));
        Value value = parseGeneric(false);
        value.typeName = std::move(typeName);
        return value;
    }
    switch (type->element) {
        case ElementKind::Opaque:
            lexer_.fail(lexer_.peek(), "attributes of type '" + typeName + "' cannot have a value");
        case ElementKind::String:
        case ElementKind::Token:
        case ElementKind::Asset: return parseStrings(*type, typeName, isArray);
        default: return parseNumbers(*type, typeName, isArray);
    }
}

Value ValueParser::parseNumbers(const ValueType& type, const std::string& typeName, bool isArray) {
    std::vector<double> numbers;
    if (!isArray) {
        parseNumericElement(type, typeName, numbers);
    } else {
        Token open = lexer_.take();
        if (!open.is('[')) {
            lexer_.fail(open, "expected '[' to start a '" + typeName + "' array, found " + describe(open));
        }
        std::optional<NumericShape> shape = plainShape(type);
        parseSeparated(
            open, ']', [&] { return "the '" + typeName + "' array"; },
            [&] { parseNumericElement(type, typeName, numbers); },
            [&] { return shape && lexer_.scanNumericRun(*shape, ']', numbers); });
    }
    return Value::numeric(typeName, std::move(numbers), type.components(), isArray);
}

void ValueParser::parseNumericElement(const ValueType& type, const std::string& typeName, std::vector<double>& out) {
    if (type.rank == 0) {
        out.push_back(parseNumber(type, typeName));
    } else if (type.rank == 1) {
        parseTuple(type, typeName, "components", out);
    } else {
        Token open = lexer_.take();
        if (!open.is('(')) {
            lexer_.fail(open, "expected a tuple of " + std::to_string(type.size) + " rows for '" + typeName +
                                  "', found " + describe(open));
        }
        std::size_t rows = 0;
        parseSeparated(
            open, ')', [&] { return "the '" + typeName + "' value"; },
            [&] {
                parseTuple(type, typeName, "components in each row", out);
                ++rows;
            });
        if (rows != static_cast<std::size_t>(type.size)) {
            lexer_.fail(open, "expected " + std::to_string(type.size) + " rows for '" + typeName + "', found " +
                                  std::to_string(rows));
        }
    }
}

void ValueParser::parseTuple(const ValueType& type, const std::string& typeName, const char* what,
                             std::vector<double>& out) {
    Token open = lexer_.take();
    if (!open.is('(')) {
        lexer_.fail(open, "expected a tuple of " + std::to_string(type.size) + " numbers for '" + typeName +
                              "', found " + describe(open));
    }
    std::size_t before = out.size();
    parseSeparated(
        open, ')', [&] { return "the '" + typeName + "' tuple"; }, [&] { out.push_back(parseNumber(type, typeName)); });
    std::size_t count = out.size() - before;
    if (count != static_cast<std::size_t>(type.size)) {
        lexer_.fail(open, "expected " + std::to_string(type.size) + " " + what + " for '" + typeName + "', found " +
                              std::to_string(count));
    }
}

double ValueParser::parseNumber(const ValueType& type, const std::string& typeName) {
    const Token& token = lexer_.peek();
    std::optional<double> value;
    if (type.element == ElementKind::Bool) {
        if (std::optional<bool> flag = boolFromToken(token)) value = *flag ? 1.0 : 0.0;
    } else if (type.element == ElementKind::Integer) {
        // A finite number, truncated toward zero as Sdf's numeric cast does (1.9 reads as 1).
        if (token.kind == TokenKind::Number && std::isfinite(token.number)) {
            value = std::trunc(token.number);
            if (*value < type.min || *value > type.max) {
                lexer_.fail(token, "value " + std::string(token.text) + " is out of range for '" + typeName + "'");
            }
        }
    } else if (token.kind == TokenKind::Number) {
        value = token.number;
    } else if (token.kind == TokenKind::Identifier || token.kind == TokenKind::String) {
        value = floatFromWord(token.kind == TokenKind::String ? token.value : token.text);
    }
    if (!value) {
        lexer_.fail(token, "expected " + expectedElement(type) + " for '" + typeName + "', found " + describe(token));
    }
    lexer_.skip();
    return *value;
}

Value ValueParser::parseStrings(const ValueType& type, const std::string& typeName, bool isArray) {
    // Asset values may also be written as quoted strings (Sdf converts them).
    bool isAsset = type.element == ElementKind::Asset;
    std::vector<std::string> strings;
    auto parseElement = [&] {
        Token token = lexer_.take();
        if (token.kind != TokenKind::String && !(isAsset && token.kind == TokenKind::Asset)) {
            lexer_.fail(token,
                        "expected " + expectedElement(type) + " for '" + typeName + "', found " + describe(token));
        }
        strings.push_back(std::move(token.value));
    };
    if (!isArray) {
        parseElement();
    } else {
        Token open = lexer_.take();
        if (!open.is('[')) {
            lexer_.fail(open, "expected '[' to start a '" + typeName + "' array, found " + describe(open));
        }
        parseSeparated(
            open, ']', [&] { return "the '" + typeName + "' array"; }, parseElement);
    }
    return Value::string(typeName, stringKindOf(type.element), std::move(strings), isArray);
}

Value ValueParser::parseDictionary() {
    Token open = lexer_.take();
    if (!open.is('{')) lexer_.fail(open, "expected '{' to start a dictionary, found " + describe(open));
    NestingGuard guard(lexer_, open);
    auto entries = std::make_shared<Dictionary>();
    std::unordered_map<std::string, std::size_t> index;
    while (true) {
        Token type = lexer_.take();
        if (type.is('}')) break;
        if (type.kind == TokenKind::End) {
            lexer_.fail(type,
                        "unexpected end of file, expected '}' to close the dictionary opened at " + location(open));
        }
        if (type.kind != TokenKind::Identifier) {
            lexer_.fail(type, "expected a value type name to start a dictionary entry, found " + describe(type));
        }
        // Unlike an attribute's, a dictionary entry's value is built as it is read: Sdf refuses
        // a type it does not know. 'dictionary' is the entry rule of its own (TOK_DICTIONARY key
        // '=' typed_dictionary).
        const bool nested = type.text == "dictionary";
        if (!nested && !findValueType(type.text)) {
            lexer_.fail(type, "unknown value type '" + std::string(type.text) + "' in a dictionary entry");
        }
        bool isArray = false;
        if (lexer_.peek().is('[') && !nested) {
            lexer_.skip();
            Token close = lexer_.take();
            if (!close.is(']')) lexer_.fail(close, "expected ']' after '[' in a type name, found " + describe(close));
            isArray = true;
        }
        Token key = lexer_.take();
        if ((key.kind != TokenKind::Identifier && key.kind != TokenKind::String) || key.newlineBefore) {
            lexer_.fail(
                key, "expected a dictionary key after type '" + std::string(type.text) + "', found " + describe(key));
        }
        std::string name = key.kind == TokenKind::String ? key.value : std::string(key.text);
        Token equals = lexer_.take();
        if (!equals.is('=')) {
            lexer_.fail(equals, "expected '=' after dictionary key '" + name + "', found " + describe(equals));
        }
        if (lexer_.peek().newlineBefore) lexer_.fail(lexer_.peek(), "expected a value after '=' on the same line");
        Value value = nested ? parseDictionary() : parseTyped(type.text, isArray);
        auto [slot, inserted] = index.emplace(name, entries->size());
        if (inserted)
            entries->emplace_back(std::move(name), std::move(value));
        else
            (*entries)[slot->second].second = std::move(value);

        const Token& next = lexer_.peek();
        if (next.is(';'))
            lexer_.skip();
        else if (!next.is('}') && !next.newlineBefore && next.kind != TokenKind::End) {
            lexer_.fail(next, "expected a line break or ';' between dictionary entries, found " + describe(next));
        }
    }
    Value dictionary;
    dictionary.typeName = "dictionary";
    dictionary.kind = ValueKind::Dictionary;
    dictionary.dictionary = std::move(entries);
    return dictionary;
}

Value ValueParser::parseNameList(const std::string& context) {
    Token open = lexer_.take();
    if (!open.is('[')) {
        lexer_.fail(open, "expected a list of names [...] for " + context + ", found " + describe(open));
    }
    std::vector<std::string> names;
    parseSeparated(open, ']', context, [&] {
        Token name = lexer_.take();
        if (name.kind != TokenKind::String) {
            lexer_.fail(name, "expected a quoted name in " + context + ", found " + describe(name));
        }
        names.push_back(std::move(name.value));
    });
    return Value::string("", ValueKind::String, std::move(names), true);
}

void ValueParser::parseLayerOffset(Value& reference, bool allowCustomData) {
    Token open = lexer_.take();
    double offset = 0.0, scale = 1.0;
    bool authored = false;
    while (true) {
        Token field = lexer_.take();
        if (field.is(')')) break;
        if (field.kind == TokenKind::End) {
            lexer_.fail(field,
                        "unexpected end of file, expected ')' to close the layer offset opened at " + location(open));
        }
        bool isNumber = field.isWord("offset") || field.isWord("scale");
        bool isCustomData = allowCustomData && field.isWord("customData");
        if (!isNumber && !isCustomData) {
            lexer_.fail(field, std::string("expected ") +
                                   (allowCustomData ? "'offset', 'scale' or 'customData'" : "'offset' or 'scale'") +
                                   " in a layer offset, found " + describe(field));
        }
        Token equals = lexer_.take();
        if (!equals.is('=')) {
            lexer_.fail(equals, "expected '=' after '" + std::string(field.text) + "', found " + describe(equals));
        }
        if (isCustomData) {
            reference.dictionary = parseDictionary().dictionary;
        } else {
            Token number = lexer_.take();
            if (number.kind != TokenKind::Number) {
                lexer_.fail(number,
                            "expected a number for '" + std::string(field.text) + "', found " + describe(number));
            }
            (field.isWord("offset") ? offset : scale) = number.number;
            authored = true;
        }
        const Token& next = lexer_.peek();
        if (next.is(';'))
            lexer_.skip();
        else if (!next.is(')') && !next.newlineBefore && next.kind != TokenKind::End) {
            lexer_.fail(next, "expected a line break or ';' between layer offset fields, found " + describe(next));
        }
    }
    if (authored) reference.numbers = {offset, scale};
}

Value ValueParser::parseGeneric(bool allowReferences) {
    const Token& token = lexer_.peek();
    switch (token.kind) {
        case TokenKind::Number: {
            double number = token.number;
            lexer_.skip();
            return Value::numeric("", {number}, 1, false);
        }
        case TokenKind::Identifier: {
            Token word = lexer_.take();
            if (word.text == "None") return Value{};
            if (word.text == "true" || word.text == "True") return Value::numeric("", {1.0}, 1, false);
            if (word.text == "false" || word.text == "False") return Value::numeric("", {0.0}, 1, false);
            if (word.text == "inf") {
                return Value::numeric("", {std::numeric_limits<double>::infinity()}, 1, false);
            }
            if (word.text == "nan") {
                return Value::numeric("", {std::numeric_limits<double>::quiet_NaN()}, 1, false);
            }
            return Value::string("", ValueKind::Token, {std::string(word.text)}, false);
        }
        case TokenKind::String: {
            Token string = lexer_.take();
            return Value::string("", ValueKind::String, {std::move(string.value)}, false);
        }
        case TokenKind::Path: {
            Token path = lexer_.take();
            return Value::string("", ValueKind::Path, {std::move(path.value)}, false);
        }
        case TokenKind::Asset: return parseAssetOrReference(allowReferences);
        case TokenKind::Punct:
            if (token.is('[')) return parseGenericList(allowReferences);
            if (token.is('(')) return parseGenericTuple(allowReferences);
            if (token.is('{')) {
                TokenKind first = lexer_.peek(1).kind;
                return first == TokenKind::String || first == TokenKind::Path ? parseMap() : parseDictionary();
            }
            break;
        case TokenKind::End: break;
    }
    lexer_.fail(token, "expected a value, found " + describe(token));
}

Value ValueParser::parseAssetOrReference(bool allowReferences) {
    Token asset = lexer_.take();
    const Token& next = lexer_.peek();
    bool isReference = allowReferences && !next.newlineBefore && (next.kind == TokenKind::Path || next.is('('));
    if (!isReference) return Value::string("", ValueKind::Asset, {std::move(asset.value)}, false);
    Value reference;
    reference.kind = ValueKind::Reference;
    reference.strings = {std::move(asset.value), ""};
    if (next.kind == TokenKind::Path) reference.strings[1] = lexer_.take().value;
    if (lexer_.peek().is('(') && !lexer_.peek().newlineBefore) parseLayerOffset(reference, true);
    return reference;
}

Value ValueParser::parseGenericList(bool allowReferences) {
    Token open = lexer_.take();
    NestingGuard guard(lexer_, open);
    std::vector<Value> items;
    parseSeparated(open, ']', "the list", [&] { items.push_back(parseGeneric(allowReferences)); });
    return flattenList(std::move(items));
}

Value ValueParser::parseGenericTuple(bool allowReferences) {
    Token open = lexer_.take();
    NestingGuard guard(lexer_, open);
    std::vector<Value> items;
    parseSeparated(open, ')', "the tuple", [&] { items.push_back(parseGeneric(allowReferences)); });
    bool allNumeric = !items.empty();
    for (const Value& item : items) allNumeric = allNumeric && item.isNumeric() && !item.isArray;
    if (allNumeric) {
        std::vector<double> numbers;
        for (const Value& item : items) numbers.insert(numbers.end(), item.numbers.begin(), item.numbers.end());
        int components = static_cast<int>(numbers.size());
        return Value::numeric("", std::move(numbers), components, false);
    }
    Value tuple;
    tuple.kind = ValueKind::List;
    tuple.items = std::move(items);
    return tuple;
}

Value ValueParser::parseMap() {
    Token open = lexer_.take();
    bool paths = lexer_.peek().kind == TokenKind::Path;
    TokenKind kind = paths ? TokenKind::Path : TokenKind::String;
    const char* what = paths ? "a path <...>" : "a quoted string";
    auto entries = std::make_shared<Dictionary>();
    parseSeparated(open, '}', paths ? "the path map" : "the string map", [&] {
        Token key = lexer_.take();
        if (key.kind != kind) lexer_.fail(key, std::string("expected ") + what + " as map key, found " + describe(key));
        if (!paths && key.value.empty()) lexer_.fail(key, "empty key in a string map");
        Token colon = lexer_.take();
        if (!colon.is(':')) lexer_.fail(colon, "expected ':' after map key, found " + describe(colon));
        Token value = lexer_.take();
        if (value.kind != kind) {
            lexer_.fail(value, std::string("expected ") + what + " as map value, found " + describe(value));
        }
        ValueKind valueKind = paths ? ValueKind::Path : ValueKind::String;
        entries->emplace_back(std::move(key.value), Value::string("", valueKind, {std::move(value.value)}, false));
    });
    Value map;
    map.kind = ValueKind::Dictionary;
    map.dictionary = std::move(entries);
    return map;
}

}  // namespace fluence::usd::detail
