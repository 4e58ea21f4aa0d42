// Decodes the values of a crate file's fields (internal to the scene library): a ValueRep and the
// data it points at into usd::Value, list ops and time samples.
//
// Values come out typed as the crate stores them: typeName is USD's name for the crate type
// ("float3[]", "token", "matrix4d", "dictionary"), numbers are flattened as value.h describes
// (quaternions reordered to (real, i, j, k), matrices row-major, half and float exactly as
// doubles). Crate-only types map onto the forms the text reader produces: SdfReference and
// SdfPayload become Reference values ({assetPath, primPath}, numbers {offset, scale} when not
// the identity, customData in `dictionary`); specifier, permission and variability become Token
// values; a variant selection map a dictionary of "string" entries; relocates a dictionary of
// Path values; token/string/path vectors Token/String/Path arrays; a layer offset vector a List
// of Reference values with empty paths.
//
// Inlined values follow OpenUSD's crateValueInliners.h: scalars of up to 4 bytes in place; int64
// and uint64 as 32-bit ints; double as float; vectors as one int8 per component; square matrices
// as their int8 diagonal (zero elsewhere); an empty dictionary. Arrays: an element count (uint32
// before 0.7.0, uint64 since), then the elements; compressed integer arrays of 16 or more
// elements use crate_integer_coding.h; compressed half/float/double arrays of 16 or more elements
// start with 'i' (integers, coded) or 't' (a uint32 table size, the table, coded indexes).
//
// Numeric arrays of 256 or more numbers (points, normals, indices, primvars) are deferred: read
// at once are only their count (and, uncompressed, that their elements lie inside the file); the
// numbers are decoded on first use (NumberArray::deferred), over a ByteReader on the file's shared
// bytes, which the array keeps alive until then. A damaged compressed array is found only then,
// and throws FileError naming the file (throwDamagedCrateFile), as a damaged file does when read.
//
// Values stored once and used by many fields (crate files deduplicate them) are decoded once and
// shared (Value copies share their numbers and dictionaries): this keeps reading fast, and a
// damaged file whose dictionaries refer to each other many times over cannot make the work grow
// exponentially. Nesting (dictionaries in dictionaries, values in values) is limited to 64
// levels, so a file whose values claim to contain themselves is an error, not a stack overflow.
// Types this reader does not decode throw CrateFormatError naming the type.
#pragma once

#include <cstdint>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "scene/crate_file.h"
#include "scene/layer.h"

namespace fluence::usd::detail {

// The crate type enum (OpenUSD crateDataTypes.h).
namespace crate_type {
enum : int {
    Bool = 1,
    UChar,
    Int,
    UInt,
    Int64,
    UInt64,
    Half,
    Float,
    Double,
    String,
    Token,
    AssetPath,
    Matrix2d,
    Matrix3d,
    Matrix4d,
    Quatd,
    Quatf,
    Quath,
    Vec2d,
    Vec2f,
    Vec2h,
    Vec2i,
    Vec3d,
    Vec3f,
    Vec3h,
    Vec3i,
    Vec4d,
    Vec4f,
    Vec4h,
    Vec4i,
    Dictionary,
    TokenListOp,
    StringListOp,
    PathListOp,
    ReferenceListOp,
    IntListOp,
    Int64ListOp,
    UIntListOp,
    UInt64ListOp,
    PathVector,
    TokenVector,
    Specifier,
    Permission,
    Variability,
    VariantSelectionMap,
    TimeSamples,
    Payload,
    DoubleVector,
    LayerOffsetVector,
    StringVector,
    ValueBlock,
    Value,
    UnregisteredValue,
    UnregisteredValueListOp,
    PayloadListOp,
    TimeCode,
    PathExpression,
    Relocates,
};
}  // namespace crate_type

// The item lists of a list op, each with its operation; `isExplicit` with no lists is an
// explicit empty list. Items are array Values (Token/String/Path arrays, Numeric arrays, or a
// List of Reference values).
struct CrateListOp {
    bool isExplicit = false;
    std::vector<std::pair<ListOpKind, Value>> lists;
};

class CrateValues {
public:
    explicit CrateValues(const CrateFile& file) : file_(file) {}

    static bool isListOp(ValueRep rep);
    static bool isTimeSamples(ValueRep rep) { return rep.type() == crate_type::TimeSamples; }

    Value value(ValueRep rep) const;
    // What an SdfUnregisteredValue (a field no schema registers) holds, as a rep of its own: a
    // string, a dictionary or an SdfUnregisteredValueListOp; any other rep as it is.
    ValueRep unwrapUnregistered(ValueRep rep) const;
    CrateListOp listOp(ValueRep rep) const;
    TimeSamples timeSamples(ValueRep rep) const;

private:
    class Depth;
    Value decode(ValueRep rep) const;
    Value numeric(ValueRep rep) const;
    Value numericArray(ValueRep rep, ByteReader& reader) const;
    Value stringArray(ValueRep rep) const;
    Value dictionary(ByteReader& reader) const;
    Value nestedValue(ByteReader& reader) const;   // a VtValue: a relative jump, then its ValueRep
    ValueRep nestedRep(ByteReader& reader) const;  // the ValueRep of such a VtValue
    Value reference(ByteReader& reader, bool withCustomData) const;
    Value listItems(int listOpType, ByteReader& reader) const;

    const CrateFile& file_;
    mutable int depth_ = 0;
    mutable std::unordered_map<std::uint64_t, Value> cache_;  // by ValueRep, for values stored in the file
    mutable std::unordered_map<std::uint64_t, CrateListOp> listOpCache_;
};

}  // namespace fluence::usd::detail
