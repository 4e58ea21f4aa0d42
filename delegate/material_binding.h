// UsdShadeMaterialBindingAPI: the material a prim is bound to, resolved as OpenUSD's
// UsdShadeMaterialBindingAPI::ComputeBoundMaterial does for the `full` purpose
// (pxr/usd/usdShade/materialBindingAPI.cpp):
//
//  - Two passes: the `full` bindings first (`material:binding:full`,
//    `material:binding:collection:full:NAME`), then, when none of them binds anything on the prim's
//    ancestry, the all-purpose ones (`material:binding`, `material:binding:collection:NAME`).
//    `preview` bindings are for previews, not final renders, and are not read here.
//  - Each pass walks from the prim up to the root. At each prim: its direct binding (one target, a
//    prim) binds when nothing closer did, or when it is `bindMaterialAs = "strongerThanDescendants"`;
//    then its collection bindings, in native property order (USD's dictionary order of their
//    names: case-insensitive, digits by value; `reorder properties` is not applied), each two
//    targets, a collection (</Prim.collection:NAME>) and a material: the first whose collection
//    holds the prim (delegate/collection_membership.h, the evaluator light linking uses:
//    includes/excludes, includeRoot, expansionRule, collections in collections, membershipExpression)
//    binds when nothing closer did, when the binding it overrides is the same prim's direct one (at
//    one prim a collection binding is stronger than the direct binding), or when it is
//    strongerThanDescendants. `weakerThanDescendants` is the default strength.
//  - A binding that cannot be used (a collection binding without exactly one collection and one
//    material among its targets, a collection no prim holds, a direct binding of several targets)
//    binds nothing: the next binding in this order applies. warnUnusableBindings says why, once per
//    relationship, naming its prim.
//  - A bound target that exists and is not a Material binds nothing (no material); one that does
//    not exist is warned about when the material is read (delegate/material_adapter.h).
// The prim's path is where membership is judged: a prim inside a native instance that renders at
// its instance-proxy path (delegate/skinned_instances.h) is judged there, and a shared prototype
// takes the bindings of the instance it is read from.
#pragma once

#include <string>

#include "delegate/material_adapter.h"  // Warn
#include "scene/stage.h"

namespace fluence::delegate {

// Path of the material bound to `prim`, or "" when none.
std::string boundMaterialPath(const usd::Stage& stage, const usd::PrimSpec& prim);

// Warns (naming `prim`) about each of its material binding relationships that binds nothing.
void warnUnusableBindings(const usd::Stage& stage, const usd::PrimSpec& prim, const Warn& warn);

// USD's dictionary order of names (TfDictionaryLessThan): letters compared ignoring case ('_'
// before them), runs of digits by their value, and case only when nothing else differs.
bool dictionaryLess(const std::string& a, const std::string& b);

}  // namespace fluence::delegate
