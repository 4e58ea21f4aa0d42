// Validity rules for the names and paths a USDA layer authors (internal to the scene library).
//
// Identifiers: a letter, '_' or UTF-8 byte, then letters, digits, '_' or UTF-8 bytes.
// Variant names: identifier characters plus '|' and '-', any of them first, after an optional
// leading '.'. Variant selections may also be empty (no selection) or a `...` expression.
// Paths: Sdf path syntax characters only; the rules say where empty paths, variant selections
// and property paths are allowed, and relative paths may not climb above the root from the
// prim they are anchored at.
#pragma once

#include <string>
#include <string_view>

namespace fluence::usd::detail {

bool isIdentifier(std::string_view name);
bool isVariantName(std::string_view name);
bool isVariantSelection(std::string_view selection);

struct PathRules {
    bool allowEmpty = false;
    bool primOnly = false;  // no property part (inherits, references, ...)
    bool allowVariantSelection = false;
};

// Empty when `path` (the text between < and >) is acceptable; otherwise what is wrong with it.
// anchorDepth is the number of prim names in the path relative paths are anchored at.
std::string pathProblem(std::string_view path, const PathRules& rules, int anchorDepth);

}  // namespace fluence::usd::detail
