#include "scene/usda_value_types.h"

#include <array>

namespace fluence::usd::detail {

namespace {

using E = ElementKind;

constexpr double kInt32Min = -2147483648.0, kInt32Max = 2147483647.0;
constexpr double kInt64Min = -9223372036854775808.0, kInt64Max = 9223372036854775807.0;

constexpr ValueType scalar(std::string_view name, E element) { return {name, element}; }
constexpr ValueType integer(std::string_view name, double min, double max) {
    return {name, E::Integer, 0, 1, min, max};
}
constexpr ValueType tuple(std::string_view name, E element, int size) {
    return {name, element, 1, size, kInt32Min, kInt32Max};
}
constexpr ValueType matrix(std::string_view name, int size) { return {name, E::Float, 2, size}; }

constexpr std::array kValueTypes = {
    scalar("bool", E::Bool),
    integer("uchar", 0.0, 255.0),
    integer("int", kInt32Min, kInt32Max),
    integer("uint", 0.0, 4294967295.0),
    integer("int64", kInt64Min, kInt64Max),
    integer("uint64", 0.0, 18446744073709551615.0),
    scalar("half", E::Float),
    scalar("float", E::Float),
    scalar("double", E::Float),
    scalar("timecode", E::Float),
    scalar("string", E::String),
    scalar("token", E::Token),
    scalar("asset", E::Asset),
    scalar("pathExpression", E::String),
    scalar("opaque", E::Opaque),
    scalar("group", E::Opaque),
    tuple("int2", E::Integer, 2),
    tuple("int3", E::Integer, 3),
    tuple("int4", E::Integer, 4),
    tuple("half2", E::Float, 2),
    tuple("half3", E::Float, 3),
    tuple("half4", E::Float, 4),
    tuple("float2", E::Float, 2),
    tuple("float3", E::Float, 3),
    tuple("float4", E::Float, 4),
    tuple("double2", E::Float, 2),
    tuple("double3", E::Float, 3),
    tuple("double4", E::Float, 4),
    tuple("point3h", E::Float, 3),
    tuple("point3f", E::Float, 3),
    tuple("point3d", E::Float, 3),
    tuple("normal3h", E::Float, 3),
    tuple("normal3f", E::Float, 3),
    tuple("normal3d", E::Float, 3),
    tuple("vector3h", E::Float, 3),
    tuple("vector3f", E::Float, 3),
    tuple("vector3d", E::Float, 3),
    tuple("color3h", E::Float, 3),
    tuple("color3f", E::Float, 3),
    tuple("color3d", E::Float, 3),
    tuple("color4h", E::Float, 4),
    tuple("color4f", E::Float, 4),
    tuple("color4d", E::Float, 4),
    tuple("texCoord2h", E::Float, 2),
    tuple("texCoord2f", E::Float, 2),
    tuple("texCoord2d", E::Float, 2),
    tuple("texCoord3h", E::Float, 3),
    tuple("texCoord3f", E::Float, 3),
    tuple("texCoord3d", E::Float, 3),
    tuple("quath", E::Float, 4),
    tuple("quatf", E::Float, 4),
    tuple("quatd", E::Float, 4),
    matrix("matrix2d", 2),
    matrix("matrix3d", 3),
    matrix("matrix4d", 4),
    matrix("frame4d", 4),
    // Legacy Sdf type names, still found in old layers.
    integer("PointIndex", kInt32Min, kInt32Max),
    integer("EdgeIndex", kInt32Min, kInt32Max),
    integer("FaceIndex", kInt32Min, kInt32Max),
    tuple("Vec2i", E::Integer, 2),
    tuple("Vec3i", E::Integer, 3),
    tuple("Vec4i", E::Integer, 4),
    tuple("Vec2h", E::Float, 2),
    tuple("Vec3h", E::Float, 3),
    tuple("Vec4h", E::Float, 4),
    tuple("Vec2f", E::Float, 2),
    tuple("Vec3f", E::Float, 3),
    tuple("Vec4f", E::Float, 4),
    tuple("Vec2d", E::Float, 2),
    tuple("Vec3d", E::Float, 3),
    tuple("Vec4d", E::Float, 4),
    tuple("Point", E::Float, 3),
    tuple("PointFloat", E::Float, 3),
    tuple("Normal", E::Float, 3),
    tuple("NormalFloat", E::Float, 3),
    tuple("Vector", E::Float, 3),
    tuple("VectorFloat", E::Float, 3),
    tuple("Color", E::Float, 3),
    tuple("ColorFloat", E::Float, 3),
    tuple("Quath", E::Float, 4),
    tuple("Quatf", E::Float, 4),
    tuple("Quatd", E::Float, 4),
    matrix("Matrix2d", 2),
    matrix("Matrix3d", 3),
    matrix("Matrix4d", 4),
    matrix("Frame", 4),
    matrix("Transform", 4),
    scalar("Schema", E::Token),
};

}  // namespace

const ValueType* findValueType(std::string_view name) {
    for (const ValueType& type : kValueTypes) {
        if (type.name == name) return &type;
    }
    return nullptr;
}

}  // namespace fluence::usd::detail
