#include "scene/crate_values.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <optional>

#include "scene/crate_integer_coding.h"

namespace fluence::usd::detail {

namespace {

namespace T = crate_type;

enum class Scalar { Bool, U8, I32, U32, I64, U64, F16, F32, F64 };
enum class Shape { Scalar, Vector, Matrix, Quaternion };

struct NumericLayout {
    const char* name;
    Scalar scalar;
    Shape shape = Shape::Scalar;
    int size = 1;  // vector length, matrix rows

    int components() const { return shape == Shape::Matrix ? size * size : size; }
};

std::size_t scalarBytes(Scalar s) {
    switch (s) {
        case Scalar::Bool:
        case Scalar::U8: return 1;
        case Scalar::F16: return 2;
        case Scalar::I32:
        case Scalar::U32:
        case Scalar::F32: return 4;
        default: return 8;
    }
}

std::optional<NumericLayout> numericLayout(int type) {
    switch (type) {
        case T::Bool: return NumericLayout{"bool", Scalar::Bool};
        case T::UChar: return NumericLayout{"uchar", Scalar::U8};
        case T::Int: return NumericLayout{"int", Scalar::I32};
        case T::UInt: return NumericLayout{"uint", Scalar::U32};
        case T::Int64: return NumericLayout{"int64", Scalar::I64};
        case T::UInt64: return NumericLayout{"uint64", Scalar::U64};
        case T::Half: return NumericLayout{"half", Scalar::F16};
        case T::Float: return NumericLayout{"float", Scalar::F32};
        case T::Double: return NumericLayout{"double", Scalar::F64};
        case T::TimeCode: return NumericLayout{"timecode", Scalar::F64};
        case T::Matrix2d: return NumericLayout{"matrix2d", Scalar::F64, Shape::Matrix, 2};
        case T::Matrix3d: return NumericLayout{"matrix3d", Scalar::F64, Shape::Matrix, 3};
        case T::Matrix4d: return NumericLayout{"matrix4d", Scalar::F64, Shape::Matrix, 4};
        case T::Quatd: return NumericLayout{"quatd", Scalar::F64, Shape::Quaternion, 4};
        case T::Quatf: return NumericLayout{"quatf", Scalar::F32, Shape::Quaternion, 4};
        case T::Quath: return NumericLayout{"quath", Scalar::F16, Shape::Quaternion, 4};
        case T::Vec2d: return NumericLayout{"double2", Scalar::F64, Shape::Vector, 2};
        case T::Vec2f: return NumericLayout{"float2", Scalar::F32, Shape::Vector, 2};
        case T::Vec2h: return NumericLayout{"half2", Scalar::F16, Shape::Vector, 2};
        case T::Vec2i: return NumericLayout{"int2", Scalar::I32, Shape::Vector, 2};
        case T::Vec3d: return NumericLayout{"double3", Scalar::F64, Shape::Vector, 3};
        case T::Vec3f: return NumericLayout{"float3", Scalar::F32, Shape::Vector, 3};
        case T::Vec3h: return NumericLayout{"half3", Scalar::F16, Shape::Vector, 3};
        case T::Vec3i: return NumericLayout{"int3", Scalar::I32, Shape::Vector, 3};
        case T::Vec4d: return NumericLayout{"double4", Scalar::F64, Shape::Vector, 4};
        case T::Vec4f: return NumericLayout{"float4", Scalar::F32, Shape::Vector, 4};
        case T::Vec4h: return NumericLayout{"half4", Scalar::F16, Shape::Vector, 4};
        case T::Vec4i: return NumericLayout{"int4", Scalar::I32, Shape::Vector, 4};
        default: return std::nullopt;
    }
}

double halfToDouble(std::uint16_t bits) {
    int exponent = (bits >> 10) & 0x1F;
    int mantissa = bits & 0x3FF;
    double sign = (bits & 0x8000) ? -1.0 : 1.0;
    if (exponent == 0) return sign * std::ldexp(mantissa, -24);
    if (exponent == 31) return mantissa ? std::nan("") : sign * INFINITY;
    return sign * std::ldexp(mantissa + 1024, exponent - 25);
}

double scalarAt(const char* p, Scalar s) {
    auto get = [p]<class V>(V) {
        V v;
        std::memcpy(&v, p, sizeof v);
        return v;
    };
    switch (s) {
        case Scalar::Bool: return get(std::uint8_t{}) != 0 ? 1.0 : 0.0;
        case Scalar::U8: return get(std::uint8_t{});
        case Scalar::I32: return get(std::int32_t{});
        case Scalar::U32: return get(std::uint32_t{});
        case Scalar::I64: return static_cast<double>(get(std::int64_t{}));
        case Scalar::U64: return static_cast<double>(get(std::uint64_t{}));
        case Scalar::F16: return halfToDouble(get(std::uint16_t{}));
        case Scalar::F32: return get(float{});
        default: return get(double{});
    }
}

// Appends one element read from `p` (the on-disk layout), quaternions reordered to (real, i, j, k).
void appendElement(const char* p, const NumericLayout& layout, std::vector<double>& out) {
    std::size_t bytes = scalarBytes(layout.scalar);
    int n = layout.components();
    if (layout.shape == Shape::Quaternion) {
        out.push_back(scalarAt(p + 3 * bytes, layout.scalar));
        n = 3;
    }
    for (int i = 0; i < n; ++i) out.push_back(scalarAt(p + static_cast<std::size_t>(i) * bytes, layout.scalar));
}

std::string typeDescription(int type) { return "crate value type " + std::to_string(type); }

// The item lists of a list op in file order, with their header bits (OpenUSD's _ListOpHeader).
constexpr std::pair<int, ListOpKind> kListOpLists[] = {
    {1 << 1, ListOpKind::Explicit}, {1 << 2, ListOpKind::Add},    {1 << 5, ListOpKind::Prepend},
    {1 << 6, ListOpKind::Append},   {1 << 3, ListOpKind::Delete}, {1 << 4, ListOpKind::Reorder},
};

Value stringValue(const char* typeName, ValueKind kind, std::string text) {
    return Value::string(typeName, kind, {std::move(text)}, false);
}

// Arrays of at least this many numbers are decoded on first use (NumberArray::deferred).
constexpr std::size_t kDeferredNumbers = 256;

// An array's element count (uint32 before 0.7.0, uint64 since), checked against the file.
std::size_t arraySize(ByteReader& reader, const CrateVersion& version) {
    std::uint64_t count = version.atLeast(0, 7, 0) ? reader.read<std::uint64_t>() : reader.read<std::uint32_t>();
    // Every element takes at least one byte, or (compressed) a quarter byte of codes.
    if (count / 4 > reader.bytes().size())
        throw CrateFormatError("an array of " + std::to_string(count) + " elements is larger than the file");
    return static_cast<std::size_t>(count);
}

bool isIntegerScalar(const NumericLayout& layout) {
    return layout.shape == Shape::Scalar && (layout.scalar == Scalar::I32 || layout.scalar == Scalar::U32 ||
                                             layout.scalar == Scalar::I64 || layout.scalar == Scalar::U64);
}

bool isCompressedArray(ValueRep rep, std::size_t count, const CrateVersion& version) {
    NumericLayout layout = *numericLayout(rep.type());
    bool isFloat = layout.shape == Shape::Scalar && rep.type() != T::TimeCode &&
                   (layout.scalar == Scalar::F16 || layout.scalar == Scalar::F32 || layout.scalar == Scalar::F64);
    return rep.isCompressed() && count >= 16 &&
           ((isIntegerScalar(layout) && version.atLeast(0, 5, 0)) || (isFloat && version.atLeast(0, 6, 0)));
}

std::size_t elementBytes(const NumericLayout& layout) {
    return scalarBytes(layout.scalar) * static_cast<std::size_t>(layout.components());
}

// Throws unless the `count` uncompressed elements at the reader's position lie inside the file.
void checkArrayFits(const ByteReader& reader, ValueRep rep, std::size_t count) {
    if (count > (reader.bytes().size() - reader.position()) / elementBytes(*numericLayout(rep.type())))
        throw CrateFormatError("an array of " + std::to_string(count) + " elements runs past the end of the file");
}

// The numbers of the numeric array `rep` whose count `reader` is at (its rank, before 0.5.0,
// already read).
std::vector<double> decodeNumbers(ByteReader& reader, ValueRep rep, const CrateVersion& version) {
    NumericLayout layout = *numericLayout(rep.type());
    std::size_t count = arraySize(reader, version);
    std::size_t bytes = elementBytes(layout);
    std::vector<double> numbers;
    if (!isCompressedArray(rep, count, version)) {
        checkArrayFits(reader, rep, count);
        std::span<const char> data = reader.take(count * bytes);
        numbers.reserve(count * static_cast<std::size_t>(layout.components()));
        for (std::size_t i = 0; i < count; ++i) appendElement(data.data() + i * bytes, layout, numbers);
        return numbers;
    }
    if (isIntegerScalar(layout)) {
        numbers.reserve(count);
        if (layout.scalar == Scalar::I64 || layout.scalar == Scalar::U64) {
            for (std::int64_t x : readCompressedInts64(reader, count))
                numbers.push_back(layout.scalar == Scalar::U64 ? static_cast<double>(static_cast<std::uint64_t>(x))
                                                               : static_cast<double>(x));
        } else {
            for (std::int32_t x : readCompressedInts32(reader, count))
                numbers.push_back(layout.scalar == Scalar::U32 ? static_cast<double>(static_cast<std::uint32_t>(x))
                                                               : x);
        }
        return numbers;
    }
    auto code = reader.read<char>();
    if (code == 'i') {
        for (std::int32_t x : readCompressedInts32(reader, count)) numbers.push_back(x);
    } else if (code == 't') {
        auto tableSize = reader.read<std::uint32_t>();
        if (tableSize > reader.bytes().size() / bytes)
            throw CrateFormatError("a lookup table of " + std::to_string(tableSize) +
                                   " entries runs past the end of the file");
        std::span<const char> table = reader.take(tableSize * bytes);
        numbers.reserve(count);
        for (std::int32_t x : readCompressedInts32(reader, count)) {
            auto at = static_cast<std::uint32_t>(x);
            if (at >= tableSize)
                throw CrateFormatError("a compressed array's table index " + std::to_string(at) + " is out of range");
            numbers.push_back(scalarAt(table.data() + at * bytes, layout.scalar));
        }
    } else {
        throw CrateFormatError("unknown compressed floating-point array code " +
                               std::to_string(static_cast<int>(code)));
    }
    return numbers;
}

}  // namespace

// Counts nesting; throws past the limit.
class CrateValues::Depth {
public:
    explicit Depth(const CrateValues& values) : values_(values) {
        if (++values_.depth_ > 64) {
            --values_.depth_;
            throw CrateFormatError("values nested more than 64 deep (a value containing itself?)");
        }
    }
    ~Depth() { --values_.depth_; }
    Depth(const Depth&) = delete;
    Depth& operator=(const Depth&) = delete;

private:
    const CrateValues& values_;
};

bool CrateValues::isListOp(ValueRep rep) {
    int t = rep.type();
    return (t >= T::TokenListOp && t <= T::UInt64ListOp) || t == T::PayloadListOp || t == T::UnregisteredValueListOp;
}

Value CrateValues::value(ValueRep rep) const {
    Depth depth(*this);
    if (rep.isInlined() || rep.payload() == 0) return decode(rep);
    if (auto cached = cache_.find(rep.bits); cached != cache_.end()) return cached->second;
    Value decoded = decode(rep);
    cache_.emplace(rep.bits, decoded);
    return decoded;
}

Value CrateValues::decode(ValueRep rep) const {
    int type = rep.type();
    if (numericLayout(type)) return numeric(rep);
    auto index = static_cast<std::uint32_t>(rep.payload());
    if (rep.isArray()) {
        if (type != T::String && type != T::Token && type != T::AssetPath && type != T::PathExpression)
            throw CrateFormatError("arrays of " + typeDescription(type) + " are not supported");
        return stringArray(rep);
    }
    switch (type) {
        case T::String: return stringValue("string", ValueKind::String, file_.string(index));
        case T::Token: return stringValue("token", ValueKind::Token, file_.token(index));
        case T::AssetPath: return stringValue("asset", ValueKind::Asset, file_.token(index));
        case T::Specifier:
            if (index > 2) throw CrateFormatError("unknown specifier " + std::to_string(index));
            return stringValue("", ValueKind::Token, index == 0 ? "def" : index == 1 ? "over" : "class");
        case T::Permission:
            if (index > 1) throw CrateFormatError("unknown permission " + std::to_string(index));
            return stringValue("", ValueKind::Token, index == 0 ? "public" : "private");
        case T::Variability:
            if (index > 2) throw CrateFormatError("unknown variability " + std::to_string(index));
            return stringValue("", ValueKind::Token, index == 0 ? "varying" : "uniform");  // 2: legacy config
        case T::ValueBlock: return Value{};
        default: break;
    }
    if (type == T::Dictionary && rep.isInlined()) {
        Value empty;
        empty.typeName = "dictionary";
        empty.kind = ValueKind::Dictionary;
        empty.dictionary = std::make_shared<Dictionary>();
        return empty;
    }
    ByteReader reader = file_.readerAt(rep.payload());
    switch (type) {
        case T::PathExpression:
            return stringValue("pathExpression", ValueKind::String, file_.string(reader.read<std::uint32_t>()));
        case T::Dictionary: return dictionary(reader);
        case T::Value:
        case T::UnregisteredValue: return nestedValue(reader);
        case T::TokenVector:
        case T::StringVector:
        case T::PathVector: return listItems(type, reader);
        case T::DoubleVector: {
            std::size_t count = reader.readCount(sizeof(double));
            std::vector<double> numbers(count);
            for (double& x : numbers) x = reader.read<double>();
            return Value::numeric("double[]", std::move(numbers), 1, true);
        }
        case T::LayerOffsetVector: {
            std::size_t count = reader.readCount(2 * sizeof(double));
            std::vector<Value> offsets;
            for (std::size_t i = 0; i < count; ++i) {
                Value offset;
                offset.kind = ValueKind::Reference;
                offset.strings = {"", ""};
                auto start = reader.read<double>();
                offset.numbers = {start, reader.read<double>()};
                offsets.push_back(std::move(offset));
            }
            return Value::list(std::move(offsets));
        }
        case T::VariantSelectionMap: {
            std::size_t count = reader.readCount(2 * sizeof(std::uint32_t));
            auto entries = std::make_shared<Dictionary>();
            for (std::size_t i = 0; i < count; ++i) {
                const std::string& set = file_.string(reader.read<std::uint32_t>());
                entries->emplace_back(
                    set, stringValue("string", ValueKind::String, file_.string(reader.read<std::uint32_t>())));
            }
            Value map;
            map.typeName = "dictionary";
            map.kind = ValueKind::Dictionary;
            map.dictionary = std::move(entries);
            return map;
        }
        case T::Relocates: {
            std::size_t count = reader.readCount(2 * sizeof(std::uint32_t));
            auto entries = std::make_shared<Dictionary>();
            for (std::size_t i = 0; i < count; ++i) {
                const std::string& source = file_.path(reader.read<std::uint32_t>());
                entries->emplace_back(source,
                                      stringValue("", ValueKind::Path, file_.path(reader.read<std::uint32_t>())));
            }
            Value map;
            map.kind = ValueKind::Dictionary;
            map.dictionary = std::move(entries);
            return map;
        }
        case T::Payload: return reference(reader, false);
        default:
            throw CrateFormatError(typeDescription(type) + " is not supported" +
                                   (isListOp(rep) || isTimeSamples(rep) ? " as a plain value" : ""));
    }
}

Value CrateValues::numeric(ValueRep rep) const {
    NumericLayout layout = *numericLayout(rep.type());
    if (rep.isArray()) {
        std::string typeName = std::string(layout.name) + "[]";
        if (rep.payload() == 0) return Value::numeric(typeName, {}, layout.components(), true);
        ByteReader reader = file_.readerAt(rep.payload());
        if (!file_.version().atLeast(0, 5, 0)) reader.read<std::uint32_t>();  // rank, always 1
        Value array = numericArray(rep, reader);
        array.typeName = typeName;
        return array;
    }
    std::vector<double> numbers;
    if (rep.isInlined()) {
        auto bits = static_cast<std::uint32_t>(rep.payload());
        char raw[4];
        std::memcpy(raw, &bits, sizeof raw);
        if (layout.shape == Shape::Vector) {
            for (int i = 0; i < layout.size; ++i) numbers.push_back(static_cast<std::int8_t>(raw[i]));
        } else if (layout.shape == Shape::Matrix) {
            numbers.assign(static_cast<std::size_t>(layout.components()), 0.0);
            for (int i = 0; i < layout.size; ++i)
                numbers[static_cast<std::size_t>(i * layout.size + i)] = static_cast<std::int8_t>(raw[i]);
        } else if (layout.shape == Shape::Quaternion) {
            throw CrateFormatError("an inlined quaternion is not a valid crate value");
        } else if (layout.scalar == Scalar::I64) {
            numbers.push_back(scalarAt(raw, Scalar::I32));
        } else if (layout.scalar == Scalar::U64) {
            numbers.push_back(scalarAt(raw, Scalar::U32));
        } else if (layout.scalar == Scalar::F64) {
            numbers.push_back(scalarAt(raw, Scalar::F32));
        } else {
            numbers.push_back(scalarAt(raw, layout.scalar));
        }
    } else {
        ByteReader reader = file_.readerAt(rep.payload());
        std::size_t bytes = scalarBytes(layout.scalar) * static_cast<std::size_t>(layout.components());
        appendElement(reader.take(bytes).data(), layout, numbers);
    }
    return Value::numeric(layout.name, std::move(numbers), layout.components(), false);
}

Value CrateValues::numericArray(ValueRep rep, ByteReader& reader) const {
    NumericLayout layout = *numericLayout(rep.type());
    const std::size_t start = reader.position();
    const std::size_t count = arraySize(reader, file_.version());
    const std::size_t size = count * static_cast<std::size_t>(layout.components());
    Value array;
    array.typeName = layout.name;
    array.kind = ValueKind::Numeric;
    array.isArray = true;
    array.components = layout.components();
    if (size < kDeferredNumbers) {
        reader.seek(start);
        array.numbers = decodeNumbers(reader, rep, file_.version());
        return array;
    }
    // Checked now, so that only a damaged compressed array can fail when decoded.
    if (!isCompressedArray(rep, count, file_.version())) checkArrayFits(reader, rep, count);
    array.numbers = NumberArray::deferred(
        size, [bytes = file_.sharedBytes(), identifier = file_.identifier(), version = file_.version(), rep, start] {
            try {
                ByteReader data(std::span<const char>(bytes->data(), bytes->size()), start);
                return decodeNumbers(data, rep, version);
            } catch (const CrateFormatError& e) {
                throwDamagedCrateFile(identifier, e.what());
            }
        });
    return array;
}

Value CrateValues::stringArray(ValueRep rep) const {
    int type = rep.type();
    const char* name = type == T::String      ? "string[]"
                       : type == T::Token     ? "token[]"
                       : type == T::AssetPath ? "asset[]"
                                              : "pathExpression[]";
    ValueKind kind = type == T::Token ? ValueKind::Token : type == T::AssetPath ? ValueKind::Asset : ValueKind::String;
    std::vector<std::string> strings;
    if (rep.payload() != 0) {
        ByteReader reader = file_.readerAt(rep.payload());
        if (!file_.version().atLeast(0, 5, 0)) reader.read<std::uint32_t>();  // rank
        std::size_t count = arraySize(reader, file_.version());
        if (count > reader.bytes().size() / sizeof(std::uint32_t))
            throw CrateFormatError("an array of " + std::to_string(count) + " strings runs past the end of the file");
        strings.reserve(count);
        for (std::size_t i = 0; i < count; ++i) {
            auto index = reader.read<std::uint32_t>();
            strings.push_back(type == T::Token ? file_.token(index) : file_.string(index));
        }
    }
    return Value::string(name, kind, std::move(strings), true);
}

Value CrateValues::dictionary(ByteReader& reader) const {
    std::size_t count = reader.readCount(sizeof(std::uint32_t) + sizeof(std::int64_t) + sizeof(std::uint64_t));
    auto entries = std::make_shared<Dictionary>();
    for (std::size_t i = 0; i < count; ++i) {
        std::string key = file_.string(reader.read<std::uint32_t>());
        entries->emplace_back(std::move(key), nestedValue(reader));
    }
    Value map;
    map.typeName = "dictionary";
    map.kind = ValueKind::Dictionary;
    map.dictionary = std::move(entries);
    return map;
}

ValueRep CrateValues::nestedRep(ByteReader& reader) const {
    std::size_t start = reader.position();
    auto jump = reader.read<std::int64_t>();
    if (jump < 0 || static_cast<std::uint64_t>(jump) > reader.bytes().size() - start)
        throw CrateFormatError("a value's offset " + std::to_string(jump) + " at " + std::to_string(start) +
                               " points outside the file");
    reader.seek(start + static_cast<std::uint64_t>(jump));
    return ValueRep{reader.read<std::uint64_t>()};
}

ValueRep CrateValues::unwrapUnregistered(ValueRep rep) const {
    if (rep.type() != T::UnregisteredValue || rep.isInlined() || rep.payload() == 0) return rep;
    ByteReader reader = file_.readerAt(rep.payload());
    return nestedRep(reader);
}

Value CrateValues::nestedValue(ByteReader& reader) const {
    ValueRep rep = nestedRep(reader);
    if (isListOp(rep) || isTimeSamples(rep))
        throw CrateFormatError("a " + typeDescription(rep.type()) + " nested in a dictionary is not supported");
    return value(rep);
}

Value CrateValues::reference(ByteReader& reader, bool withCustomData) const {
    Value ref;
    ref.kind = ValueKind::Reference;
    std::string asset = file_.string(reader.read<std::uint32_t>());
    std::string prim = file_.path(reader.read<std::uint32_t>());
    ref.strings = {std::move(asset), std::move(prim)};
    if (withCustomData || file_.version().atLeast(0, 8, 0)) {
        auto offset = reader.read<double>();
        auto scale = reader.read<double>();
        if (offset != 0.0 || scale != 1.0) ref.numbers = {offset, scale};
    }
    if (withCustomData) {
        Depth depth(*this);
        Value customData = dictionary(reader);
        if (!customData.dictionary->empty()) ref.dictionary = customData.dictionary;
    }
    return ref;
}

Value CrateValues::listItems(int type, ByteReader& reader) const {
    auto strings = [&](const char* name, ValueKind kind, auto lookup) {
        std::size_t count = reader.readCount(sizeof(std::uint32_t));
        std::vector<std::string> out;
        out.reserve(count);
        for (std::size_t i = 0; i < count; ++i) out.push_back(lookup(reader.read<std::uint32_t>()));
        return Value::string(name, kind, std::move(out), true);
    };
    auto numbers = [&]<class Int>(const char* name, Int) {
        std::size_t count = reader.readCount(sizeof(Int));
        std::vector<double> out;
        for (std::size_t i = 0; i < count; ++i) out.push_back(static_cast<double>(reader.read<Int>()));
        return Value::numeric(name, std::move(out), 1, true);
    };
    switch (type) {
        case T::TokenListOp:
        case T::TokenVector:
            return strings("token[]", ValueKind::Token, [&](std::uint32_t i) { return file_.token(i); });
        case T::StringListOp:
        case T::StringVector:
            return strings("string[]", ValueKind::String, [&](std::uint32_t i) { return file_.string(i); });
        case T::PathListOp:
        case T::PathVector: return strings("", ValueKind::Path, [&](std::uint32_t i) { return file_.path(i); });
        case T::IntListOp: return numbers("int[]", std::int32_t{});
        case T::UIntListOp: return numbers("uint[]", std::uint32_t{});
        case T::Int64ListOp: return numbers("int64[]", std::int64_t{});
        case T::UInt64ListOp: return numbers("uint64[]", std::uint64_t{});
        case T::UnregisteredValueListOp: {
            // SdfUnregisteredValue items, each a VtValue (in practice the text of a value).
            std::size_t count = reader.readCount(sizeof(std::int64_t));
            std::vector<Value> items;
            for (std::size_t i = 0; i < count; ++i) items.push_back(nestedValue(reader));
            return Value::list(std::move(items));
        }
        case T::ReferenceListOp:
        case T::PayloadListOp: {
            std::size_t count = reader.readCount(2 * sizeof(std::uint32_t));
            std::vector<Value> items;
            for (std::size_t i = 0; i < count; ++i) items.push_back(reference(reader, type == T::ReferenceListOp));
            return Value::list(std::move(items));
        }
        default: throw CrateFormatError(typeDescription(type) + " list items are not supported");
    }
}

CrateListOp CrateValues::listOp(ValueRep rep) const {
    Depth depth(*this);
    if (auto cached = listOpCache_.find(rep.bits); cached != listOpCache_.end()) return cached->second;
    ByteReader reader = file_.readerAt(rep.payload());
    auto header = reader.read<std::uint8_t>();
    CrateListOp op;
    op.isExplicit = header & 1;
    for (auto [bit, kind] : kListOpLists)
        if (header & bit) op.lists.emplace_back(kind, listItems(rep.type(), reader));
    listOpCache_.emplace(rep.bits, op);
    return op;
}

TimeSamples CrateValues::timeSamples(ValueRep rep) const {
    Depth depth(*this);
    ByteReader reader = file_.readerAt(rep.payload());
    auto follow = [&] {
        std::size_t start = reader.position();
        auto jump = reader.read<std::int64_t>();
        if (jump < 0 || static_cast<std::uint64_t>(jump) > reader.bytes().size() - start)
            throw CrateFormatError("time samples at " + std::to_string(start) + " point outside the file");
        reader.seek(start + static_cast<std::uint64_t>(jump));
    };
    follow();
    Value times = value(ValueRep{reader.read<std::uint64_t>()});
    if (!times.isNumeric() || times.components != 1) throw CrateFormatError("time sample times are not doubles");
    follow();
    std::size_t count = reader.readCount(sizeof(std::uint64_t));
    if (count != times.numbers.size())
        throw CrateFormatError(std::to_string(times.numbers.size()) + " sample times but " + std::to_string(count) +
                               " sample values");
    TimeSamples samples;
    samples.reserve(count);
    for (std::size_t i = 0; i < count; ++i) {
        ValueRep valueRep{reader.read<std::uint64_t>()};
        samples.emplace_back(times.numbers[i], value(valueRep));
    }
    std::stable_sort(samples.begin(), samples.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    return samples;
}

}  // namespace fluence::usd::detail
