// Validity rules for the names and paths a USDA layer authors (internal to the scene library).
//
// Identifiers (prim names, property and type names): UTF-8, an XID_Start character or '_', then
// XID_Continue characters (unicode_xid.h), as OpenUSD's SdfPath rules. Variant names:
// XID_Continue characters plus '|' and '-', any of them first, after an optional leading '.'.
// Variant selections may also be empty (no selection) or a `...` expression. Paths: Sdf path
// syntax characters and XID_Continue characters only; the rules say where empty paths, variant
// selections and property paths are allowed, whether a path must be absolute, and relative paths
// may not climb above the root from the prim they are anchored at; </> alone is no prim path. Malformed UTF-8 is never valid.
#pragma once

#include <string>
#include <string_view>

namespace fluence::usd::detail {

// Empty when `name` is an identifier; otherwise what is wrong with it ("U+222B '∫' cannot be
// part of a name").
std::string identifierProblem(std::string_view name);
bool isVariantName(std::string_view name);
bool isVariantSelection(std::string_view selection);

struct PathRules {
    bool allowEmpty = false;
    bool primOnly = false;  // no property part (inherits, references, ...)
    bool allowVariantSelection = false;
    bool absoluteOnly = false;  // references and payloads: Sdf does not anchor their prim paths
};

// Empty when `path` (the text between < and >) is acceptable; otherwise what is wrong with it.
// anchorDepth is the number of prim names in the path relative paths are anchored at.
std::string pathProblem(std::string_view path, const PathRules& rules, int anchorDepth);

}  // namespace fluence::usd::detail
