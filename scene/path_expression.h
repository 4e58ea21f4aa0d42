// SdfPathExpression: OpenUSD's set expressions over prim paths (pxr/usd/sdf/pathExpression.h),
// which UsdCollectionAPI's `membershipExpression` holds, parsed and evaluated for prims.
//
// Atoms are path patterns and expression references. A pattern is a path whose elements may hold
// glob wildcards (`*`, `?`, `[abc]`, `[a-z]`, `[!a]`), `//` for any number of levels (zero
// included; a trailing `//` also matches the prefix's descendants), and a brace-enclosed predicate
// expression after or instead of an element's text (`/World//{isa:Mesh}`, scene/prim_predicates.h):
// calls joined by `not`, `and`, `or` and whitespace (an implied and), with parentheses. A pattern
// not starting with `/` is relative to the anchor (the collection's prim): `.`, `..`, `Child/*`.
// A pattern ending in a property element (`/Prim.attr`) matches no prim. A reference `%/Prim:name`
// or `%:name` (the anchor's collection `name`) stands for that collection's members; `%_` (the
// weaker expression) for nothing. Atoms are joined by `~` (complement), whitespace (implied union),
// `+` (union), `&` (intersection) and `-` (difference), in this order of precedence (highest
// first, each left-associative, as OpenUSD's parser builds them), and grouped by parentheses.
//
// A pattern matches a prim's path itself; descendants only through `//`. Anything else is a
// PathExpressionError whose what() is "column N: ..." (N 1-based).
#pragma once

#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "scene/prim_predicates.h"
#include "scene/stage.h"

namespace fluence::usd {

class PathExpressionError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class PathExpression {
public:
    // A reference %<prim>:<name>: the collection's prim (absolute) and name.
    struct Reference {
        std::string prim, name;
    };
    // Whether the prim at `path` belongs to the collection a reference names.
    using ReferenceMembership = std::function<bool(const Reference&, const std::string& path)>;

    // Parses `text`; relative patterns and references are anchored at the prim path `anchor`.
    PathExpression(std::string_view text, const std::string& anchor);
    ~PathExpression();
    PathExpression(PathExpression&&) noexcept;
    PathExpression& operator=(PathExpression&&) noexcept;

    // The collections it references (%_ aside), to resolve before evaluating.
    const std::vector<Reference>& references() const { return references_; }

    // Whether the prim at absolute `path` of `stage` matches.
    bool matches(const std::string& path, const Stage& stage, const ReferenceMembership& membership) const;

    struct Node;

private:
    std::unique_ptr<Node> root_;
    std::vector<Reference> references_;
};

}  // namespace fluence::usd
