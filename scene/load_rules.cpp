#include "scene/load_rules.h"

#include <algorithm>

#include "scene/namespace_remap.h"

namespace fluence::usd {

using detail::hasPathPrefix;

LoadRules LoadRules::loadNone() {
    LoadRules rules;
    rules.unload("/");
    return rules;
}

void LoadRules::setRule(const std::string& primPath, bool load) {
    std::erase_if(rules_, [&](const auto& rule) { return hasPathPrefix(rule.first, primPath); });
    rules_[primPath] = load;
}

bool LoadRules::isLoaded(const std::string& primPath) const {
    const std::pair<const std::string, bool>* governing = nullptr;
    for (const auto& rule : rules_)
        if (hasPathPrefix(primPath, rule.first) && (!governing || rule.first.size() > governing->first.size()))
            governing = &rule;
    if (!governing || governing->second) return true;
    // Unloaded, unless a load rule lies below with no rule between it and the prim.
    auto below = [&](const std::string& path, const std::string& ancestor) {
        return path != ancestor && hasPathPrefix(path, ancestor);
    };
    return std::any_of(rules_.begin(), rules_.end(), [&](const auto& rule) {
        return rule.second && below(rule.first, primPath) &&
               std::none_of(rules_.begin(), rules_.end(), [&](const auto& between) {
                   return below(between.first, primPath) && below(rule.first, between.first);
               });
    });
}

}  // namespace fluence::usd
