#include "delegate/imageable.h"

#include "delegate/implicit_geometry.h"
#include "delegate/prim_reader.h"

namespace fluence::delegate {

bool isImaged(const usd::PrimSpec& prim, double time) {
    PrimReader reader(prim, time);
    if (reader.token({"visibility"}, "inherited") == "invisible") return false;
    std::string purpose = reader.token({"purpose"}, "default");
    return purpose != "guide" && purpose != "proxy";
}

bool isGeometryType(const std::string& typeName) { return typeName == "Mesh" || isImplicitType(typeName); }

}  // namespace fluence::delegate
