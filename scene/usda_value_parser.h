// Parses USDA values into usd::Value (internal to the scene library).
//
//   typed value     := 'None' | path | element | '[' (element (',' element)* ','?)? ']' (T[])
//   element         := number | 'inf' | 'nan' | '"inf"' | '"-inf"' | '"nan"'  (float scalars)
//                    | number                     (integers: a finite number, truncated)
//                    | number | true | false | yes | no, in any case, bare or quoted    (bool)
//                    | '(' number (',' number)* ','? ')'                         (vectors)
//                    | '(' tuple (',' tuple)* ','? ')'                           (matrices)
//                    | string                                     (string, token types)
//                    | asset | string                                         (asset types)
// as Sdf's parser value context converts them (parserHelpers.h: Value::Get<T>). A path stands
// for a value of any type and is kept as a Path value under the declared type name.
//   dictionary      := '{' (type ['[' ']'] (identifier | string) '=' value sep)* '}'
//                      (a known value type: unlike an attribute's, an unknown one is an error)
//   generic value   := 'None' | number | identifier | string | path | reference
//                    | '[' generic,* ']' | '(' generic,* ')' | '{' dictionary-or-map '}'
//   map             := '{' (string ':' string | path ':' path),* '}'
//   reference       := asset [path] [layerOffset]      (an asset alone is an Asset value)
//   layerOffset     := '(' ('offset' '=' number | 'scale' '=' number
//                           | 'customData' '=' dictionary) sep... ')'
// where sep is ';' or a line break. Typed values are checked against the declared type (tuple
// arity, integer ranges, bool literals, string versus number) and written straight into the
// flat number/string arrays, so a large point array costs no per-element allocation.
// Generic lists flatten to a typed array when their items agree (all numbers, all tuples of the
// same size, all strings, all paths); otherwise they become a List value.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include <vector>

#include "scene/usda_lexer.h"
#include "scene/usda_value_types.h"
#include "scene/value.h"

namespace fluence::usd::detail {

// A bool element as Sdf reads one: any number (true when not zero), or true/false/yes/no in any
// case, bare or quoted ("1" and "0" quoted too); nullopt for any other token.
std::optional<bool> boolFromToken(const Token& token);

class ValueParser {
public:
    explicit ValueParser(Lexer& lexer) : lexer_(lexer) {}

    // A value of the declared type (baseType without "[]"), or None. Values of unknown types are
    // parsed generically and keep the authored type name.
    Value parseTyped(std::string_view baseType, bool isArray);
    // An untyped value (metadata). With allowReferences, an asset followed on the same line by a
    // path or a layer offset is read as a Reference.
    Value parseGeneric(bool allowReferences);
    // '{' typed entries '}': a Dictionary value.
    Value parseDictionary();
    // '[' "name", ... ']' (reorder statements): a String array.
    Value parseNameList(const std::string& context);
    // '(' offset = x; scale = y [customData = {...}] ')' after an asset path; fills
    // reference.numbers = {offset, scale} (and reference.dictionary with customData).
    void parseLayerOffset(Value& reference, bool allowCustomData);

    // Items separated by ',' up to `close` (a trailing ',' is allowed); `open` is the opening
    // token, already taken. `context` names the construct in error messages: a string, or a
    // function returning one (so hot loops build no message unless they fail). Before each item,
    // parseRun may read a run of items and the close at once (Lexer::scanNumericRun), returning
    // true when it did.
    template <class Context, class ParseItem, class ParseRun>
    void parseSeparated(const Token& open, char close, Context&& context, ParseItem&& parseItem, ParseRun&& parseRun);
    template <class Context, class ParseItem>
    void parseSeparated(const Token& open, char close, Context&& context, ParseItem&& parseItem) {
        parseSeparated(open, close, context, parseItem, [] { return false; });
    }

private:
    Value parseNumbers(const ValueType& type, const std::string& typeName, bool isArray);
    Value parseStrings(const ValueType& type, const std::string& typeName, bool isArray);
    void parseNumericElement(const ValueType& type, const std::string& typeName, std::vector<double>& out);
    void parseTuple(const ValueType& type, const std::string& typeName, const char* what, std::vector<double>& out);
    double parseNumber(const ValueType& type, const std::string& typeName);
    Value parseGenericList(bool allowReferences);
    Value parseGenericTuple(bool allowReferences);
    Value parseMap();
    Value parseAssetOrReference(bool allowReferences);

    Lexer& lexer_;
};

template <class Context, class ParseItem, class ParseRun>
void ValueParser::parseSeparated(const Token& open, char close, Context&& context, ParseItem&& parseItem,
                                 ParseRun&& parseRun) {
    auto contextText = [&]() -> std::string {
        if constexpr (std::is_invocable_v<Context>)
            return context();
        else
            return context;
    };
    auto failAtEnd = [&](const Token& end) {
        lexer_.fail(end, std::string("unexpected end of file, expected '") + close + "' to close " + contextText() +
                             " opened at " + std::to_string(open.line) + ":" + std::to_string(open.column));
    };
    while (true) {
        if (parseRun()) return;
        if (lexer_.peek().is(close)) break;
        if (lexer_.peek().kind == TokenKind::End) failAtEnd(lexer_.peek());
        parseItem();
        const Token& next = lexer_.peek();
        if (next.is(',')) {
            if (next.newlineBefore) lexer_.fail(next, "unexpected line break before ','");
            lexer_.skip();
        } else if (!next.is(close)) {
            if (next.kind == TokenKind::End) failAtEnd(next);
            lexer_.fail(
                next, std::string("expected ',' or '") + close + "' in " + contextText() + ", found " + describe(next));
        }
    }
    lexer_.skip();
}

}  // namespace fluence::usd::detail
