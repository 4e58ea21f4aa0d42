#include "delegate/collection_membership.h"

#include <vector>

#include "delegate/prim_reader.h"

namespace fluence::delegate {

namespace {

using Rule = CollectionMembership::Rule;
using RuleMap = std::map<std::string, Rule>;

constexpr std::string_view kCollectionTag = ".collection:";

// Merges collection `name` of `prim` into `rules`; `chain` holds the collections being read
// (prim path + ".collection:" + name), to break cycles.
void merge(const usd::Stage& stage, const usd::PrimSpec& prim, const std::string& name, bool includeRootFallback,
           double time, const Warn& warn, std::set<std::string>& chain, RuleMap& rules) {
    const std::string base = "collection:" + name + ":";
    PrimReader reader(prim, time);
    const std::string ruleName = reader.token({(base + "expansionRule").c_str()}, "expandPrims");
    if (ruleName != "expandPrims" && ruleName != "expandPrimsAndProperties" && ruleName != "explicitOnly")
        warn(prim.path,
             base + "expansionRule '" + ruleName + "' is not one of UsdCollectionAPI's; read as expandPrims");
    const Rule rule = ruleName == "explicitOnly" ? Rule::ExplicitOnly : Rule::ExpandPrims;

    auto targets = [&](const std::string& relationship) {
        const usd::RelationshipSpec* rel = prim.relationship(relationship);
        return rel && !rel->blocked ? rel->targets : std::vector<std::string>{};
    };
    std::vector<std::string> includes = targets(base + "includes");
    if (rule != Rule::ExplicitOnly && reader.boolean({(base + "includeRoot").c_str()}, includeRootFallback))
        includes.push_back("/");
    for (const std::string& target : includes) {
        const std::size_t tag = target.find(kCollectionTag);
        if (tag != std::string::npos) {  // another collection: its rules merged in
            if (!chain.insert(target).second) {
                warn(prim.path, base + "includes: <" + target + "> includes itself through a cycle; left out");
                continue;
            }
            const usd::PrimSpec* owner = stage.prim(target.substr(0, tag));
            if (!owner)
                warn(prim.path, base + "includes: no prim holds the collection <" + target + ">; left out");
            else
                merge(stage, *owner, target.substr(tag + kCollectionTag.size()), false, time, warn, chain, rules);
            chain.erase(target);
        } else if (target.empty() || target[0] != '/' || target.find('.') != std::string::npos) {
            warn(prim.path, base + "includes: <" + target + "> is not an absolute prim path; left out");
        } else {
            rules[target] = rule;
        }
    }
    for (const std::string& target : targets(base + "excludes")) rules[target] = Rule::Exclude;
}

// The path of collection `name` of the prim at `prim`: </Prim.collection:name>.
std::string collectionPath(const std::string& prim, const std::string& name) {
    return prim + std::string(kCollectionTag) + name;
}

}  // namespace

CollectionMembership CollectionMembership::read(const usd::Stage& stage, const usd::PrimSpec& prim,
                                                const std::string& name, bool includeRootFallback, double time,
                                                const Warn& warn) {
    std::set<std::string> chain{collectionPath(prim.path, name)};
    return read(stage, prim, name, includeRootFallback, time, warn, chain);
}

CollectionMembership CollectionMembership::read(const usd::Stage& stage, const usd::PrimSpec& prim,
                                                const std::string& name, bool includeRootFallback, double time,
                                                const Warn& warn, std::set<std::string>& chain) {
    CollectionMembership c;
    merge(stage, prim, name, includeRootFallback, time, warn, chain, c.rules_);
    if (!c.rules_.empty()) return c;
    const std::string attribute = "collection:" + name + ":membershipExpression";
    const std::string text = PrimReader(prim, time).token({attribute.c_str()}, "");
    if (text.find_first_not_of(" \t") == std::string::npos) return c;
    try {
        auto expression = std::make_shared<usd::PathExpression>(text, prim.path);
        auto references = std::make_shared<std::map<std::string, CollectionMembership>>();
        for (const usd::PathExpression::Reference& r : expression->references()) {
            const std::string key = collectionPath(r.prim, r.name);
            if (references->count(key)) continue;
            const usd::PrimSpec* owner = stage.prim(r.prim);
            if (!owner) {
                warn(prim.path, attribute + ": no prim holds the collection <" + key + ">; it holds nothing");
            } else if (!chain.insert(key).second) {
                warn(prim.path, attribute + ": <" + key + "> refers to itself through a cycle; it holds nothing");
            } else {
                (*references)[key] = read(stage, *owner, r.name, false, time, warn, chain);
                chain.erase(key);
            }
        }
        c.expression_ = std::move(expression);
        c.references_ = std::move(references);
        c.stage_ = &stage;
    } catch (const usd::PathExpressionError& e) {
        warn(prim.path, attribute + " \"" + text + "\": " + e.what() + "; the collection holds nothing");
    }
    return c;
}

bool CollectionMembership::contains(const std::string& path) const {
    if (expression_)
        return expression_->matches(path, *stage_, [&](const usd::PathExpression::Reference& r, const std::string& p) {
            auto found = references_->find(collectionPath(r.prim, r.name));
            return found != references_->end() && found->second.contains(p);
        });
    for (std::string p = path;; p = parentPath(p)) {
        auto found = rules_.find(p);
        if (found != rules_.end() && (found->second != Rule::ExplicitOnly || p == path))
            return found->second != Rule::Exclude;
        if (p == "/") return false;
    }
}

bool CollectionMembership::holdsEverything() const {
    return rules_.size() == 1 && rules_.begin()->first == "/" && rules_.begin()->second == Rule::ExpandPrims;
}

}  // namespace fluence::delegate
