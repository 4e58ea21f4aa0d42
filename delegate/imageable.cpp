#include "delegate/imageable.h"

#include <stdexcept>

#include "delegate/implicit_geometry.h"
#include "delegate/prim_reader.h"

namespace fluence::delegate {

IncludedPurposes IncludedPurposes::fromNames(const std::vector<std::string>& names) {
    IncludedPurposes purposes{false, false, false};
    for (const std::string& name : names) {
        if (name == "render") purposes.render = true;
        else if (name == "proxy") purposes.proxy = true;
        else if (name == "guide") purposes.guide = true;
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

bool isImaged(const usd::PrimSpec& prim, double time, const IncludedPurposes& purposes) {
    PrimReader reader(prim, time);
    if (reader.token({"visibility"}, "inherited") == "invisible") return false;
    return purposes.includes(reader.token({"purpose"}, "default"));
}

bool isGeometryType(const std::string& typeName) { return typeName == "Mesh" || isImplicitType(typeName); }

}  // namespace fluence::delegate
