// USDA text for values (internal to the scene library): the inverse of usda_value_parser.h, used
// by the layer writer (scene/usda_writer.h).
//
// Every value is written so that Fluence's reader gives it back exactly:
//   - Numbers: doubles (and untyped numbers) in the shortest form that reads back to the same
//     double (std::to_chars' digits), laid out as USD lays them out (decimal notation from 1e-6
//     up to 1e15, else 1e-7, 2.5e15); integer types in plain digits; typed bools as 1/0 and the bool
//     metadata fields (active, hidden, ...) as true/false; NaN and infinities as nan, inf, -inf.
//     A float-typed number that is exactly a float is written as the shortest form of that float
//     (as USD writes a float: 0.1f is "0.1"), and a half-typed number that is exactly a half as
//     USD prints halves (the float, 6 significant digits); either reads back to the same float or
//     half. Other numbers of these types (the reader keeps the authored decimal as a double) are
//     written as doubles, so no digit of them is lost.
//   - Strings and tokens: USD's quoting rules (Sdf_FileIOUtility::Quote): double quotes unless the
//     text holds '"' and no '\'', triple quotes when it holds a line break (which is then written
//     as is), \\ \t \r (and \n in one-line strings) escaped, the quote character escaped,
//     valid UTF-8 kept, other bytes outside printable ASCII as \xNN.
//   - Asset paths @...@, or @@@...@@@ when the path holds '@' (with \@@@ for '@@@'); paths <...>.
//   - Typed values (attributes, time samples, dictionary entries) by their declared type; untyped
//     values (metadata) by their shape, as the reader's generic value rules read them back.
// Multi-line values (dictionaries, reference lists) are indented from `indent` (4 spaces a level).
#pragma once

#include <string>
#include <string_view>

#include "scene/value.h"

namespace fluence::usd::detail {

// A string, token, name or key in quotes, by USD's rules.
std::string quoteString(std::string_view text);
// @path@ or @@@path@@@.
std::string quoteAssetPath(std::string_view path);

// A number of the type named `baseType` ("float", "point3f", "int", "" for untyped), as above.
std::string formatNumber(double number, std::string_view baseType);

// The value of an attribute or dictionary entry declared `typeName` ("float3[]", "token", ...).
void writeTypedValue(std::string& out, const Value& value, std::string_view typeName, int indent);

// An untyped (metadata) value. `key` is the metadata field it is written for, which picks the
// forms some fields need (true/false for bool fields, quoted kind, bare permission).
void writeMetadataValue(std::string& out, const Value& value, std::string_view key, int indent);

// '{' entries '}' for a Dictionary value: typed entries, or a string or path map.
void writeDictionary(std::string& out, const Value& dictionary, int indent);

// A composition arc target (references, payloads, subLayers): @asset@</path> (offset; scale; customData).
void writeReference(std::string& out, const Value& reference, int indent);

}  // namespace fluence::usd::detail
