// Relocates (internal to the scene library; USD's `relocates` and Pcp's relocation arcs): a layer
// stack moves a prim that one of its composition arcs brings in to another path of its own
// namespace, `relocates = { </World/Set/Chair>: </World/Chair> }`, or removes it from namespace
// (`</World/Set/Lamp>: <>`).
//
// Where they are authored: the layer metadata `relocates` (USD 24.11 onwards). Older files author
// `relocates` in prim metadata, with paths relative to that prim; a layer's prim relocates are read
// only when its layer metadata has none, as Pcp does. Over a layer stack, the strongest layer's
// relocation of a source wins.
//
// What is rejected, each with a warning at the `relocates` entry (USD's
// PcpErrorInvalidAuthoredRelocation, PcpErrorInvalidConflictingRelocation and
// PcpErrorInvalidSameTargetRelocations): a source or target that is not a prim path; a root prim as
// the source; a target equal to its own source, an ancestor of it or a descendant of it; two sources
// moved to one target (both dropped); a target that is another relocation's source (both dropped)
// or lies below one; a source that lies below another relocation's source.
//
// What a relocation does: the prim index at the target gets a relocation arc to the source
// (scene/prim_index.h), so the target composes from the source's ancestral arcs, while opinions
// authored at the source in the relocating stack are ignored; the source's name leaves its
// parent's children and the target's name joins its parent's (editChildNames); paths that reach
// the relocating stack across an arc are moved with the prim (apply).
#pragma once

#include <map>
#include <set>
#include <string>
#include <vector>

#include "scene/composition_types.h"

namespace fluence::usd::detail {

struct Relocation {
    std::string source;
    std::string target;  // empty: the source is removed from namespace
    SourceLocation location;
};

class Relocates {
public:
    // The valid relocations that `layers` (a layer stack, strongest first) author; the invalid ones
    // are reported to `log`.
    static Relocates gather(const std::vector<const Layer*>& layers, CompositionLog& log);

    bool empty() const { return relocations_.empty(); }
    const Relocation* bySource(const std::string& path) const;
    const Relocation* byTarget(const std::string& path) const;

    // `path` (a prim or property path) with every relocation of it or of an ancestor applied, as
    // often as they apply (a source may lie below another relocation's target). Paths below a
    // removed source are left as they are.
    std::string apply(std::string path) const;

    // The children of the prim `parent`, as named so far (`names`), after its relocations: a child
    // relocated to another name under the same parent is renamed in place, one relocated elsewhere
    // (or removed) leaves, and children relocated here from elsewhere join at the end, in name
    // order. The names of relocated sources go to `prohibited`: no opinion may bring them back.
    // Returns whether `names` changed.
    bool editChildNames(const std::string& parent, std::vector<std::string>& names,
                        std::set<std::string>& prohibited) const;

private:
    std::vector<Relocation> relocations_;
    std::map<std::string, std::size_t> bySource_, byTarget_;
    std::map<std::string, std::vector<std::size_t>> byParent_;  // by the parent of the source or target
};

}  // namespace fluence::usd::detail
