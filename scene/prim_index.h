// The prim index: every site that holds opinions about one composed prim, in strength order
// (internal to the scene library; USD spec "Composition", "LIVRPS Strength Ordering").
//
// An index is a tree of nodes. Each node is a site — a layer stack and a path in that stack's
// namespace — reached from its parent node by one composition arc: the root node is the prim's
// path in the stage's root layer stack (Local opinions); below it hang the arcs authored on the
// specs at each node: Inherits, Variants, References, Payloads and Specializes, and the
// relocation arcs of the node's layer stack. Arcs found in a referenced site are added below that
// site's node, so composition applies recursively.
//
// Strength order is the tree walked depth first, each node before its children, children in
// LIVRPS order: by arc type (inherit, variant, relocate, reference, payload, specialize), then
// the arc introduced at the deeper namespace level first (an arc authored on /World/Chair/Geom is
// stronger than one inherited from an arc on /World/Chair), then authored arcs before implied
// ones, then in the order of the composed arc list. Specializes subtrees are moved after
// everything else, so they are the weakest opinions of the whole prim, and an implied specialize
// (see below) precedes the arc it was implied from.
//
// Ancestral arcs: the index of /World/Chair/Geom starts as the index of /World/Chair with
// "Geom" appended to every node's path (so a reference on /World/Chair to @chair.usda@</Asset>
// brings in chair.usda's /Asset/Geom), then adds the arcs authored at those paths.
//
// Implied inherits and specializes (USD spec "Inherits": class opinions from the referencing
// layer stack): a class arc found inside a reference is also added, mapped through the reference,
// to the layer stack that holds the reference, and so on up to the root layer stack, so that the
// stage's own layers can override a class that a referenced asset uses.
//
// Variant selections (USD spec "VariantSets"): a node's variant sets are the composed
// `variantSets` list of its specs; each set's selection is the strongest `variants` opinion found
// anywhere in the index (StageOptions' selections override them). Variant sets are evaluated after
// all other arcs known so far, strongest node first, because a selection may be authored in any
// site, including sites brought in by references. A selected variant is a node whose path holds
// the selection ("/Asset{look=red}"); sets nested in a variant hang below it.
//
// Payloads (USD's UsdStageLoadRules): a payload arc is added only when StageOptions::loadRules
// load the prim being indexed; otherwise the index remembers that it has an unloaded payload.
//
// Relocates (scene/relocates.h; Pcp's relocation arcs, scene/relocation_arcs.cpp): when a node's
// site is the target of a relocation in its layer stack, the node's ancestral arcs other than
// variants are superseded (made inert), and a relocate node for the source site is added below it,
// holding the source's whole prim index (its ancestral arcs) but none of the opinions authored at
// the source itself: relocate nodes are inert (no specs, no arcs of their own, and so in every
// child index too). Nodes inside that subtree that are relocation sources of their own stack are
// made inert as well, so no opinion lands on two prims. Paths crossing an arc into a layer stack
// are moved by that stack's relocations (mapToRoot).
//
// Cycles: an arc whose site is the site of one of its ancestors in the tree, or an ancestor or a
// descendant prim of it in the same layer stack, would compose forever; it is reported and left
// out, as is a relocation whose source index needs the relocation itself. Nodes without any spec
// (and without such nodes below) are culled.
#pragma once

#include <initializer_list>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "scene/composition_types.h"
#include "scene/layer_stack.h"
#include "scene/namespace_remap.h"

namespace fluence::usd::detail {

enum class ArcType { Root, Inherit, Variant, Relocate, Reference, Payload, Specialize };  // strongest first

struct IndexNode {
    const LayerStack* stack = nullptr;
    std::string path;  // in the stack's namespace; may hold variant selections
    ArcType arc = ArcType::Root;
    int parent = -1;
    std::vector<int> children;                       // strongest first
    std::shared_ptr<const MapFunction> mapToParent;  // null for the identity (root, variants)
    LayerOffset offset;                              // this node's time codes to the stage's
    int namespaceDepth = 0;                          // depth of the prim on which the arc was authored
    int siblingNumber = 0;                           // position in the composed arc list
    int impliedRank = 0;                             // 0 for arcs authored at the parent; else the order of implication
    int origin = -1;                                 // implied arcs: the node they were implied from
    bool inert = false;                              // contributes no opinions and no arcs (relocation sources)
    std::vector<std::pair<int, SpecRef>> specs;      // (layer in the stack, spec), strongest first
};

class PrimIndex {
public:
    const std::string& path() const { return path_; }
    const std::vector<IndexNode>& nodes() const { return nodes_; }
    // Node ids, strongest first.
    std::vector<int> strengthOrder() const;
    // A path in `node`'s namespace, as the stage sees it.
    std::string mapToRoot(int node, std::string path) const;
    // A path in `node`'s namespace, as its parent node sees it.
    std::string mapToParent(int node, std::string path) const;
    // True when some arc other than local opinions contributes (what makes instancing matter).
    bool hasArcs() const { return nodes_.size() > 1; }
    // Equal for prims whose arcs (sites, variant selections, layer offsets) are all the same: the
    // prims that USD would let share one instance prototype.
    std::string instanceKey() const;
    // True when some site authors a payload that the load rules left out.
    bool hasUnloadedPayload() const { return unloadedPayload_; }

private:
    friend class PrimIndexer;
    std::string path_;
    std::vector<IndexNode> nodes_;
    bool unloadedPayload_ = false;
    int impliedCount_ = 0;
    std::map<std::string, std::set<std::string>> variantSets_;  // set -> variants, as found
};

class PrimIndexer {
public:
    PrimIndexer(LayerRegistry& registry, CompositionLog& log, const StageOptions& options)
        : registry_(registry), log_(log), options_(options) {}

    PrimIndex root(const LayerStack& stack, const std::string& path);
    // Below an instanceable prim (`belowInstance`), the root layer stack's own opinions do not
    // apply (USD spec "Instancing"): the root node then holds no specs.
    PrimIndex child(const PrimIndex& parent, const std::string& name, bool belowInstance);

    // Total nodes made so far, for the caller's work budget.
    std::size_t nodesMade() const { return nodesMade_; }

private:
    struct Work;
    struct ArcItem;

    static constexpr std::size_t kMaxNodesPerPrim = 1000;

    void expand(PrimIndex& index, Work& work);
    void finish(PrimIndex& index, Work& work);
    int addNode(PrimIndex& index, IndexNode node, bool checkCycle, const SourceLocation& where, Work& work);
    // Inserts node `id` among its parent's children at its strength.
    static void insertChild(PrimIndex& index, int id);
    // True (after one warning per index) when `adding` more nodes would pass kMaxNodesPerPrim.
    bool overflows(const PrimIndex& index, std::size_t adding, const SourceLocation& where, Work& work);
    void addArcs(PrimIndex& index, int node, Work& work);
    void addVariants(PrimIndex& index, int node, Work& work);
    void addReference(PrimIndex& index, int node, ArcType arc, const ArcItem& item, int sibling, Work& work);
    void addClass(PrimIndex& index, int node, ArcType arc, const ArcItem& item, int sibling, Work& work);
    void implyClass(PrimIndex& index, int classNode, Work& work);
    // Relocation arcs (scene/relocation_arcs.cpp).
    void addRelocation(PrimIndex& index, int node, Work& work);
    PrimIndex indexAt(const LayerStack& stack, const std::string& path);
    int graft(PrimIndex& index, int parent, const PrimIndex& source);
    void elideRelocationSources(PrimIndex& index, int node) const;
    std::vector<ArcItem> composeArcs(const IndexNode& node, std::initializer_list<const char*> keys) const;
    const std::vector<int>& orderOf(const PrimIndex& index);
    std::optional<std::string> selectionFor(const PrimIndex& index, const std::string& set);
    void checkOptionSelections(const PrimIndex& index);
    std::vector<std::pair<int, SpecRef>> specsAt(const LayerStack& stack, const std::string& path) const;
    void cull(PrimIndex& index) const;

    LayerRegistry& registry_;
    CompositionLog& log_;
    const StageOptions& options_;
    std::size_t nodesMade_ = 0;
    std::vector<int> order_;  // strength order of the index being expanded (orderOf)
    const PrimIndex* orderFor_ = nullptr;
    std::size_t orderSize_ = 0;
    std::vector<std::pair<const LayerStack*, std::string>> relocating_;  // sources being indexed
};

}  // namespace fluence::usd::detail
