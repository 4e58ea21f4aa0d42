// A USD value as authored in a layer: the scene description's one value type.
//
// Values keep the authored type name ("point3f[]", "matrix4d", "token", "asset", ...) and store
// their payload in one of a few flat forms, so that large arrays (points, indices) cost one
// allocation and the render side can read them without per-element dispatch:
//   - Numeric: every scalar, vector, quaternion, matrix, bool and integer type, element-major,
//     `components` doubles per element (float3 -> 3, matrix4d -> 16, quatf -> 4 in USD's text
//     order (real, i, j, k), bool -> 1 as 0/1). float/half values are stored exactly as doubles.
//     The numbers are a NumberArray: copies of a value share them (scene/number_array.h).
//   - String / Token / Asset / Path: one std::string per element (asset paths without the @s,
//     paths without the <>).
//   - Reference: a composition-arc target, strings = {assetPath, primPath} (either may be empty);
//     numbers = {offset, scale} when a layer offset was authored.
//   - List: a heterogeneous list or tuple from untyped metadata, items in `items`.
//   - Dictionary: `dictionary` holds named entries (each a Value with its own type name).
//   - Blocked: the literal `None` (a value block in USD).
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "scene/number_array.h"

namespace fluence::usd {

enum class ValueKind { Blocked, Numeric, String, Token, Asset, Path, Reference, List, Dictionary };

struct Value;
using Dictionary = std::vector<std::pair<std::string, Value>>;  // authored order kept

struct Value {
    std::string typeName;  // authored type ("float3[]"); empty for untyped metadata values
    ValueKind kind = ValueKind::Blocked;
    bool isArray = false;  // authored with [] (an array type or a bracketed metadata list)
    int components = 1;    // doubles per element, for Numeric
    NumberArray numbers;
    std::vector<std::string> strings;
    std::vector<Value> items;
    std::shared_ptr<const Dictionary> dictionary;

    // Number of elements: numbers/components for Numeric, strings.size() for string kinds,
    // items.size() for List, entries for Dictionary, 0 for Blocked.
    std::size_t size() const;

    bool isBlocked() const { return kind == ValueKind::Blocked; }
    bool isNumeric() const { return kind == ValueKind::Numeric; }
    bool isStringLike() const {
        return kind == ValueKind::String || kind == ValueKind::Token || kind == ValueKind::Asset ||
               kind == ValueKind::Path;
    }

    // Scalar accessors: the first element, when the kind matches.
    std::optional<double> asDouble() const;
    std::optional<std::string> asString() const;
    // Looks up a dictionary entry (nullptr when this is not a dictionary or the key is absent).
    const Value* find(const std::string& key) const;

    // Human-readable form for messages and tests, close to USDA syntax (arrays are elided past
    // a few elements).
    std::string toString() const;

    // Builders used by the parser and by tests.
    static Value numeric(std::string typeName, std::vector<double> numbers, int components, bool isArray);
    static Value string(std::string typeName, ValueKind kind, std::vector<std::string> strings, bool isArray);
    // An untyped bracketed list of `items` (kind List).
    static Value list(std::vector<Value> items);
};

}  // namespace fluence::usd
