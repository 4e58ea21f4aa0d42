#include "scene/layer.h"

#include <string_view>

namespace fluence::usd {

std::string SourceLocation::str() const { return file + ":" + std::to_string(line) + ":" + std::to_string(column); }

const MetadataEntry* findMetadata(const Metadata& metadata, const std::string& key) {
    for (auto it = metadata.rbegin(); it != metadata.rend(); ++it) {
        if (it->key == key) return &*it;
    }
    return nullptr;
}

const AttributeSpec* PrimSpec::attribute(const std::string& attributeName) const {
    for (const AttributeSpec& spec : attributes) {
        if (spec.name == attributeName) return &spec;
    }
    return nullptr;
}

const RelationshipSpec* PrimSpec::relationship(const std::string& relationshipName) const {
    for (const RelationshipSpec& spec : relationships) {
        if (spec.name == relationshipName) return &spec;
    }
    return nullptr;
}

const PrimSpec* PrimSpec::child(const std::string& childName) const {
    for (const auto& spec : children) {
        if (spec->name == childName) return spec.get();
    }
    return nullptr;
}

const PrimSpec* Layer::primAtPath(const std::string& path) const {
    if (path.size() < 2 || path.front() != '/') return nullptr;
    const std::vector<std::unique_ptr<PrimSpec>>* siblings = &rootPrims;
    const PrimSpec* found = nullptr;
    std::string_view rest(path);
    rest.remove_prefix(1);
    while (true) {
        std::size_t slash = rest.find('/');
        std::string_view name = rest.substr(0, slash);
        found = nullptr;
        for (const auto& prim : *siblings) {
            if (prim->name == name) {
                found = prim.get();
                break;
            }
        }
        if (!found || slash == std::string_view::npos) return found;
        siblings = &found->children;
        rest.remove_prefix(slash + 1);
    }
}

}  // namespace fluence::usd
