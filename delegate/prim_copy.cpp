#include "delegate/prim_copy.h"

#include <algorithm>
#include <iterator>

namespace fluence::delegate {

std::unique_ptr<usd::PrimSpec> copyPrim(const usd::PrimSpec& prim) {
    auto copy = std::make_unique<usd::PrimSpec>();
    copy->specifier = prim.specifier;
    copy->typeName = prim.typeName;
    copy->name = prim.name;
    copy->path = prim.path;
    copy->metadata = prim.metadata;
    copy->attributes = prim.attributes;
    copy->relationships = prim.relationships;
    copy->location = prim.location;
    for (const auto& child : prim.children) copy->children.push_back(copyPrim(*child));
    return copy;
}

void setArray(usd::PrimSpec& prim, const std::string& name, const std::string& typeName, std::vector<double> values,
              int components) {
    auto it = std::find_if(prim.attributes.begin(), prim.attributes.end(),
                           [&](const usd::AttributeSpec& a) { return a.name == name; });
    if (it == prim.attributes.end()) {
        prim.attributes.push_back({});
        it = std::prev(prim.attributes.end());
        it->name = name;
        it->typeName = typeName;
    }
    it->timeSamples = {};
    it->hasDefault = true;
    it->defaultValue = usd::Value::numeric(typeName, std::move(values), components, true);
}

}  // namespace fluence::delegate
