// The predicate functions of OpenUSD's collection predicate library
// (pxr/usd/usd/collectionPredicateLibrary.cpp), which path expressions call inside braces
// (`/World//{isa:Mesh}`, scene/path_expression.h), evaluated on a composed prim:
//   abstract(b = true)   the prim or an ancestor is a class
//   defined(b = true)    the prim and its ancestors are def or class (none is only an over)
//   model(b = true)      its kind is model or one derived from it (group, assembly, component)
//   group(b = true)      its kind is group or assembly
//   kind:k1,k2           its kind is one of them, or derives from one (strict=true: exactly)
//   specifier:s1,s2      its specifier is one of def, over, class
//   isa:T1,T2            its type is one of them, or derives from one (strict=true: exactly), by
//                        the UsdGeom, UsdLux, UsdVol, UsdSkel and UsdShade schema hierarchy
//   hasAPI:A1,A2         it applies one of these API schemas (instanceName=x: that instance of a
//                        multiple-apply schema; without it, any instance)
// `model` and `group` read the prim's own kind; USD also requires its ancestors to be groups.
// `variant` is not supported.
#pragma once

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "scene/stage.h"

namespace fluence::usd {

// One call: positional arguments and keyword arguments, as written (strings, numbers, true/false).
struct PredicateCall {
    std::string name;
    std::vector<std::string> args;
    std::map<std::string, std::string> keywords;
};

// An unknown function or a bad argument; what() says which.
class PredicateError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// The parent of an absolute prim path ("/" for a root prim), for walks up the namespace.
inline std::string parentPrimPath(const std::string& path) {
    const std::size_t slash = path.find_last_of('/');
    return slash == 0 ? "/" : path.substr(0, slash);
}

// Throws PredicateError unless `call` is a function of the library with valid arguments.
void checkPredicate(const PredicateCall& call);

// Whether the prim at `path` of `stage` satisfies `call` (false for a path with no prim).
bool evaluatePredicate(const PredicateCall& call, const Stage& stage, const std::string& path);

}  // namespace fluence::usd
