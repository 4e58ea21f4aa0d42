#include "delegate/imageable.h"

#include <stdexcept>

#include "delegate/implicit_geometry.h"
#include "delegate/prim_reader.h"

namespace fluence::delegate {

IncludedPurposes IncludedPurposes::fromNames(const std::vector<std::string>& names) {
    IncludedPurposes purposes{false, false, false};
    for (const std::string& name : names) {
        if (name == "render")
            purposes.render = true;
        else if (name == "proxy")
            purposes.proxy = true;
        else if (name == "guide")
            purposes.guide = true;
        else if (name != "default" && name != "geometry")
            throw std::invalid_argument("unknown purpose '" + name + "' (default, render, proxy, guide)");
    }
    return purposes;
}

bool IncludedPurposes::includes(const std::string& purpose) const {
    if (purpose == "render") return render;
    if (purpose == "proxy") return proxy;
    if (purpose == "guide") return guide;
    return true;  // "default", and values USD does not define, render
}

namespace {

// A UsdGeomImageable token attribute. A value of another type is no opinion, as
// UsdAttribute::Get<TfToken> reads it; `ignored` is told.
std::string imageableToken(const PrimReader& reader, const char* name, const std::string& fallback,
                           const std::function<void(const SceneError&)>& ignored) {
    std::optional<usd::Value> v = reader.value(name);
    if (!v) return fallback;
    if (v->typeName != "token" || v->isArray || v->strings.size() != 1) {
        ignored(SceneError(reader.prim().location.str() + ": " + reader.path() + ": '" + name +
                           "' must be a token, got " + (v->typeName.empty() ? "" : v->typeName + " ") + v->toString()));
        return fallback;
    }
    return v->strings[0];
}

}  // namespace

bool isImaged(const usd::PrimSpec& prim, double time, const IncludedPurposes& purposes,
              const std::function<void(const SceneError&)>& ignored) {
    PrimReader reader(prim, time);
    if (imageableToken(reader, "visibility", "inherited", ignored) == "invisible") return false;
    return purposes.includes(imageableToken(reader, "purpose", "default", ignored));
}

bool isGeometryType(const std::string& typeName) {
    return typeName == "Mesh" || typeName == "TetMesh" || isImplicitType(typeName);
}

}  // namespace fluence::delegate
