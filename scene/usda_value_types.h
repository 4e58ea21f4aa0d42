// The value types an attribute or dictionary entry may declare (internal to the scene library).
//
// Each entry tells the value parser the shape of one element: a scalar, a tuple of `size`
// numbers (vectors, colours, quaternions), or `size` tuples of `size` numbers (matrices,
// flattened row-major); and how each number is checked (bool, integer range, any float). Legacy
// Sdf names (Vec3f, PointFloat, Matrix4d, ...) map to the same shapes. 'dictionary' is no value
// type (Sdf's value factories have none): only a dictionary entry may be one, by its own rule.
#pragma once

#include <string_view>

namespace fluence::usd::detail {

enum class ElementKind { Bool, Integer, Float, String, Token, Asset, Opaque };

struct ValueType {
    std::string_view name;
    ElementKind element;
    int rank = 0;                 // 0 scalar, 1 tuple, 2 tuple of tuples
    int size = 1;                 // tuple length (and row count for rank 2)
    double min = 0.0, max = 0.0;  // inclusive range, for Integer elements

    int components() const { return rank == 0 ? 1 : rank == 1 ? size : size * size; }
};

// The type named `name` (without "[]"), or nullptr for an unknown type name.
const ValueType* findValueType(std::string_view name);

}  // namespace fluence::usd::detail
