// Scene-description paths as strings, and the namespace maps that carry them across composition
// arcs (internal to the scene library).
//
// Paths use Sdf syntax: "/World/Chair" (a prim), "/World/Chair.size" (a property),
// "/World{look=red}Chair" (a prim inside the variant "red" of the variant set "look" on /World),
// relative forms "../Geom", "./Geom", "Geom", ".size" in relationship targets and connections.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace fluence::usd::detail {

// "/A{v=x}{w=y}B/C" -> "/A/B/C".
std::string stripVariantSelections(std::string_view path);

// The path of a child prim: ("/", "A") -> "/A", ("/A", "B") -> "/A/B", ("/A{v=x}", "B") ->
// "/A{v=x}B".
std::string childPrimPath(std::string_view parent, std::string_view name);

// True when `path` is `prefix` or lies below it (a descendant prim, a property of either, or a
// variant of either). "/" is a prefix of every absolute path.
bool hasPathPrefix(std::string_view path, std::string_view prefix);

// The absolute form of `path` (returned unchanged when already absolute), with relative paths
// anchored at the prim `anchor` (absolute, without variant selections).
std::string absolutePath(std::string_view anchor, std::string_view path);

// The number of prim names in an absolute prim path ("/" -> 0, "/A{v=x}B" -> 2).
int pathDepth(std::string_view path);

// The prim names of an absolute prim path without variant selections ("/A/B" -> {"A", "B"}).
std::vector<std::string> primNames(std::string_view path);

// Maps paths from the namespace at one end of a composition arc to the other: an arc from the
// prim `source` (in the arc's target layer stack) to `target` (where it is composed) maps
// `source` and everything below it to `target`; every other absolute path maps to itself, as
// USD's root identity mapping does, so paths outside the arc's namespace (global classes, shared
// materials) stay as they are.
class MapFunction {
public:
    MapFunction(std::string source, std::string target);

    // `path` must be absolute.
    std::string map(std::string_view path) const;

private:
    std::string source_;
    std::string target_;
};

}  // namespace fluence::usd::detail
