#include "delegate/prim_reader.h"

namespace fluence::delegate {

std::optional<usd::Value> PrimReader::value(const std::string& name) const {
    const usd::AttributeSpec* a = prim_.attribute(name);
    return a ? usd::Stage::resolve(*a, time_) : std::nullopt;
}

std::optional<usd::Value> PrimReader::value(std::initializer_list<const char*> names) const {
    for (const char* n : names)
        if (prim_.attribute(n)) return value(std::string(n));
    return std::nullopt;
}

void PrimReader::fail(const std::string& message) const {
    throw SceneError(prim_.location.str() + ": " + prim_.path + ": " + message);
}

namespace {

const char* firstAuthored(const usd::PrimSpec& prim, std::initializer_list<const char*> names) {
    for (const char* n : names)
        if (prim.attribute(n)) return n;
    return *names.begin();
}

}  // namespace

double PrimReader::number(std::initializer_list<const char*> names, double fallback) const {
    auto v = value(names);
    if (!v) return fallback;
    if (!v->isNumeric() || v->isArray || v->numbers.size() != 1)
        fail("attribute '" + std::string(firstAuthored(prim_, names)) + "' must be a scalar number, got " +
             v->toString());
    return v->numbers[0];
}

bool PrimReader::boolean(std::initializer_list<const char*> names, bool fallback) const {
    return number(names, fallback ? 1.0 : 0.0) != 0.0;
}

std::string PrimReader::token(std::initializer_list<const char*> names, const std::string& fallback) const {
    auto v = value(names);
    if (!v) return fallback;
    if (!v->isStringLike() || v->isArray || v->strings.size() != 1)
        fail("attribute '" + std::string(firstAuthored(prim_, names)) + "' must be a token or string, got " +
             v->toString());
    return v->strings[0];
}

Vec3d PrimReader::vec3(std::initializer_list<const char*> names, const Vec3d& fallback) const {
    auto v = value(names);
    if (!v) return fallback;
    if (!v->isNumeric() || v->components != 3 || v->numbers.size() != 3)
        fail("attribute '" + std::string(firstAuthored(prim_, names)) + "' must be a 3-vector, got " + v->toString());
    return {v->numbers[0], v->numbers[1], v->numbers[2]};
}

std::optional<std::vector<double>> PrimReader::numbers(const std::string& name, int components) const {
    auto v = value(name);
    if (!v) return std::nullopt;
    if (!v->isNumeric() || v->components != components)
        fail("attribute '" + name + "' must be an array of " + std::to_string(components) + "-component values, got " +
             v->toString());
    return std::move(v->numbers);
}

std::optional<std::vector<std::string>> PrimReader::strings(const std::string& name) const {
    auto v = value(name);
    if (!v) return std::nullopt;
    if (!v->isStringLike())
        fail("attribute '" + name + "' must be an array of tokens or strings, got " + v->toString());
    return std::move(v->strings);
}

std::optional<std::string> PrimReader::attributeMetadata(const std::string& attribute, const std::string& key) const {
    const usd::AttributeSpec* a = prim_.attribute(attribute);
    if (!a) return std::nullopt;
    const usd::MetadataEntry* e = usd::findMetadata(a->metadata, key);
    return e ? e->value.asString() : std::nullopt;
}

}  // namespace fluence::delegate
