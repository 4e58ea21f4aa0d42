#include "delegate/material_binding.h"

#include <algorithm>
#include <cctype>
#include <vector>

#include "delegate/collection_membership.h"
#include "scene/prim_predicates.h"

namespace fluence::delegate {

namespace {

constexpr std::string_view kCollectionTag = ".collection:";

// The names of one purpose's binding relationships: the direct one and the prefix of the
// collection ones ("" for the all-purpose pass).
struct Purpose {
    const char* direct;
    const char* collectionPrefix;
};
constexpr Purpose kFull{"material:binding:full", "material:binding:collection:full:"};
constexpr Purpose kAllPurpose{"material:binding", "material:binding:collection:"};

bool strongerThanDescendants(const usd::RelationshipSpec& rel) {
    const usd::MetadataEntry* e = usd::findMetadata(rel.metadata, "bindMaterialAs");
    return e && e->value.asString().value_or("") == "strongerThanDescendants";
}

bool isPropertyPath(const std::string& path) { return path.find('.') != std::string::npos; }

std::vector<std::string> targetsOf(const usd::RelationshipSpec& rel, const std::string& owner) {
    std::vector<std::string> targets;
    if (rel.blocked) return targets;
    for (const std::string& t : rel.targets) targets.push_back(resolveTargetPath(owner, t));
    return targets;
}

// A collection binding's two targets: the collection's owner prim and name, and the material.
struct CollectionBinding {
    std::string owner, name, material;
};

// Why `rel` (a collection binding of the prim at `owner`) binds nothing on `stage`, or "" when it
// can bind; `binding` is filled when it can.
std::string collectionBindingProblem(const usd::Stage& stage, const usd::RelationshipSpec& rel,
                                     const std::string& owner, CollectionBinding& binding) {
    const std::vector<std::string> targets = targetsOf(rel, owner);
    if (targets.size() != 2 || isPropertyPath(targets[0]) == isPropertyPath(targets[1]))
        return "has " + std::to_string(targets.size()) + (targets.size() == 1 ? " target" : " targets") +
               "; a collection binding needs two, a collection and a material";
    const std::string& collection = isPropertyPath(targets[0]) ? targets[0] : targets[1];
    binding.material = isPropertyPath(targets[0]) ? targets[1] : targets[0];
    const std::size_t tag = collection.find(kCollectionTag);
    if (tag == std::string::npos) return "targets <" + collection + ">, which is not a collection";
    binding.owner = collection.substr(0, tag);
    binding.name = collection.substr(tag + kCollectionTag.size());
    if (!stage.prim(binding.owner)) return "targets the collection <" + collection + ">, but no prim " + binding.owner;
    const usd::PrimSpec& holder = *stage.prim(binding.owner);
    const std::string properties = "collection:" + binding.name + ":";
    auto authored = [&](const auto& list) {
        return std::any_of(list.begin(), list.end(), [&](const auto& p) { return p.name.starts_with(properties); });
    };
    if (!authored(holder.attributes) && !authored(holder.relationships) &&
        !usd::evaluatePredicate({"hasAPI", {"CollectionAPI"}, {{"instanceName", binding.name}}}, stage, holder.path))
        return "targets the collection <" + collection + ">, which " + binding.owner + " does not define";
    return "";
}

// The direct binding of `prim` for `purpose`: its one target, "" when it has none or several.
std::string directTarget(const usd::RelationshipSpec* rel, const std::string& owner) {
    if (!rel) return "";
    const std::vector<std::string> targets = targetsOf(*rel, owner);
    return targets.size() == 1 && !isPropertyPath(targets[0]) ? targets[0] : "";
}

// The collection binding relationships of `prim` for `purpose`, in native property order.
std::vector<const usd::RelationshipSpec*> collectionBindings(const usd::PrimSpec& prim, const Purpose& purpose) {
    const std::string prefix = purpose.collectionPrefix;
    const bool allPurpose = &purpose == &kAllPurpose;
    std::vector<const usd::RelationshipSpec*> rels;
    for (const usd::RelationshipSpec& rel : prim.relationships)
        if (rel.name.size() > prefix.size() && rel.name.starts_with(prefix) &&
            (!allPurpose || rel.name.find(':', prefix.size()) == std::string::npos))
            rels.push_back(&rel);
    std::sort(rels.begin(), rels.end(), [](const auto* a, const auto* b) { return dictionaryLess(a->name, b->name); });
    return rels;
}

// The material `purpose`'s bindings bind to the prim at `path`, "" when none does.
std::string boundFor(const usd::Stage& stage, const std::string& path, const Purpose& purpose) {
    std::string bound, winnerOwner;
    const Warn quiet = [](const std::string&, const std::string&) {};  // warnUnusableBindings speaks
    for (std::string at = path; !at.empty() && at != "/"; at = parentPath(at)) {
        const usd::PrimSpec* prim = stage.prim(at);
        if (!prim) continue;
        const usd::RelationshipSpec* direct = prim->relationship(purpose.direct);
        if (const std::string target = directTarget(direct, at);
            !target.empty() && (bound.empty() || strongerThanDescendants(*direct))) {
            bound = target;
            winnerOwner = at;
        }
        for (const usd::RelationshipSpec* rel : collectionBindings(*prim, purpose)) {
            CollectionBinding binding;
            if (!collectionBindingProblem(stage, *rel, at, binding).empty()) continue;
            const CollectionMembership members = CollectionMembership::read(
                stage, *stage.prim(binding.owner), binding.name, false, usd::kDefaultTime, quiet);
            if (!members.contains(path)) continue;
            if (bound.empty() || winnerOwner == at || strongerThanDescendants(*rel)) {
                bound = binding.material;
                winnerOwner = at;
                break;  // the first collection that holds the prim is the one that counts
            }
        }
    }
    return bound;
}

}  // namespace

std::string boundMaterialPath(const usd::Stage& stage, const usd::PrimSpec& prim) {
    std::string bound = boundFor(stage, prim.path, kFull);
    if (bound.empty()) bound = boundFor(stage, prim.path, kAllPurpose);
    // A target that exists but is not a Material binds nothing (UsdShade's ComputeBoundMaterial).
    const usd::PrimSpec* target = bound.empty() ? nullptr : stage.prim(bound);
    return target && target->typeName != "Material" ? "" : bound;
}

void warnUnusableBindings(const usd::Stage& stage, const usd::PrimSpec& prim, const Warn& warn) {
    for (const usd::RelationshipSpec& rel : prim.relationships) {
        if (!rel.name.starts_with("material:binding") || rel.blocked) continue;
        std::string problem;
        if (rel.name.starts_with("material:binding:collection:")) {
            CollectionBinding binding;
            problem = collectionBindingProblem(stage, rel, prim.path, binding);
        } else if (rel.targets.size() > 1) {
            problem = "has " + std::to_string(rel.targets.size()) + " targets; a direct binding needs one material";
        }
        if (!problem.empty()) warn(prim.path, rel.name + " " + problem + "; ignored, the next binding applies");
    }
}

bool dictionaryLess(const std::string& a, const std::string& b) {
    std::size_t i = 0, j = 0;
    auto digit = [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; };
    auto letterKey = [](char c) {
        return c == '_' ? '@' : static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    };
    while (i < a.size() && j < b.size()) {
        if (digit(a[i]) && digit(b[j])) {
            std::size_t ei = i, ej = j;
            while (ei < a.size() && digit(a[ei])) ++ei;
            while (ej < b.size() && digit(b[ej])) ++ej;
            std::size_t si = a.find_first_not_of('0', i), sj = b.find_first_not_of('0', j);
            si = std::min(si, ei);
            sj = std::min(sj, ej);
            if (ei - si != ej - sj) return ei - si < ej - sj;
            if (const int c = a.compare(si, ei - si, b, sj, ej - sj); c != 0) return c < 0;
            i = ei;
            j = ej;
            continue;
        }
        const char x = letterKey(a[i]), y = letterKey(b[j]);
        if (x != y) return x < y;
        ++i;
        ++j;
    }
    if (i != a.size() || j != b.size()) return i == a.size();  // a prefix first
    return a < b;
}

}  // namespace fluence::delegate
