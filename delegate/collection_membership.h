// UsdCollectionAPI membership: which prims a collection holds, read as OpenUSD's
// UsdCollectionAPI::ComputeMembershipQuery and UsdCollectionMembershipQuery::IsPathIncluded define it
// (pxr/usd/usd/collectionAPI.h) for prims.
//
// A collection in relationship mode is a map from paths to rules: each `includes` target gets the
// collection's expansionRule, `includeRoot` (unless the rule is explicitOnly) adds the root with it,
// and each `excludes` target is excluded; an `includes` target naming another collection
// (</Prim.collection:name>) merges that collection's map in, its entries overriding earlier ones for
// the same path (a cycle is warned about and broken). A prim belongs to the collection when the
// nearest of its ancestors-or-self in the map includes it: an exclude does not, explicitOnly only
// when it names the prim itself (else the search goes on up), expandPrims and
// expandPrimsAndProperties do. A collection with an empty map is in expression mode: its
// `membershipExpression` (an SdfPathExpression, scene/path_expression.h, anchored at the
// collection's prim) decides, prim by prim (no expansion: `/World/*` holds the children of World,
// `/World//` all its descendants); references to other collections (`%/Prim:name`, `%:name`) are
// resolved, a cycle warned about and broken; an unauthored or empty expression holds nothing. A
// syntax error in an expression is warned about (naming its column) and the collection holds nothing.
#pragma once

#include <map>
#include <memory>
#include <set>
#include <string>

#include "delegate/material_adapter.h"  // Warn
#include "scene/path_expression.h"
#include "scene/stage.h"

namespace fluence::delegate {

class CollectionMembership {
public:
    enum class Rule { ExpandPrims, ExplicitOnly, Exclude };

    // Collection `name` of `prim` (its properties collection:<name>:...), read at `time`.
    // `includeRootFallback` is includeRoot's value when unauthored: false for UsdCollectionAPI,
    // true for UsdLux's lightLink and shadowLink collections of a light.
    static CollectionMembership read(const usd::Stage& stage, const usd::PrimSpec& prim, const std::string& name,
                                     bool includeRootFallback, double time, const Warn& warn);

    // Whether the prim at `path` belongs to the collection.
    bool contains(const std::string& path) const;
    // Whether it holds every prim (the root expanded, nothing excluded).
    bool holdsEverything() const;

private:
    static CollectionMembership read(const usd::Stage& stage, const usd::PrimSpec& prim, const std::string& name,
                                     bool includeRootFallback, double time, const Warn& warn,
                                     std::set<std::string>& chain);

    std::map<std::string, Rule> rules_;
    // Expression mode: the expression, the collections it references (by prim + ".collection:" +
    // name) and the stage its predicates read.
    std::shared_ptr<const usd::PathExpression> expression_;
    std::shared_ptr<const std::map<std::string, CollectionMembership>> references_;
    const usd::Stage* stage_ = nullptr;
};

}  // namespace fluence::delegate
