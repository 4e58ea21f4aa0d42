// Relocation arcs of the prim index (scene/prim_index.h, "Relocates"; USD's Pcp evaluates them as
// _EvalNodeRelocations): the prim index at a relocation target takes the index of the relocation
// source, minus the source's own opinions.
#include <algorithm>

#include "scene/prim_index.h"

namespace fluence::usd::detail {

namespace {

// The node and its subtree contribute nothing any more.
void elide(std::vector<IndexNode>& nodes, int n) {
    nodes[n].inert = true;
    nodes[n].specs.clear();
    for (int c : nodes[n].children) elide(nodes, c);
}

}  // namespace

void PrimIndexer::addRelocation(PrimIndex& index, int n, Work& work) {
    const LayerStack& stack = *index.nodes_[n].stack;
    const Relocation* relocation = stack.relocates.byTarget(index.nodes_[n].path);
    if (!relocation) return;
    // The relocation supersedes the ancestral arcs found at the target, variants excepted.
    for (int c : index.nodes_[n].children)
        if (index.nodes_[c].arc != ArcType::Variant) elide(index.nodes_, c);

    std::pair<const LayerStack*, std::string> site(&stack, relocation->source);
    if (std::find(relocating_.begin(), relocating_.end(), site) != relocating_.end()) {
        log_.warn("relocation cycle: <" + relocation->source + "> is needed to compose itself (" + "relocate <" +
                      relocation->source + "> -> <" + relocation->target + "> ignored)",
                  relocation->location, index.path_);
        return;
    }
    relocating_.push_back(site);
    PrimIndex source = indexAt(stack, relocation->source);
    relocating_.pop_back();
    for (const auto& [layer, spec] : source.nodes_.front().specs)
        if (spec.prim)
            log_.warn("opinions at <" + relocation->source + "> are ignored: relocates move that prim to <" +
                          relocation->target + ">",
                      spec.prim->location, index.path_);
    if (overflows(index, source.nodes_.size(), relocation->location, work)) return;
    elideRelocationSources(index, graft(index, n, source));
}

PrimIndex PrimIndexer::indexAt(const LayerStack& stack, const std::string& path) {
    std::vector<std::string> names = primNames(path);
    PrimIndex index = root(stack, "/" + names.front());
    for (std::size_t i = 1; i < names.size(); ++i) index = child(index, names[i], false);
    return index;
}

int PrimIndexer::graft(PrimIndex& index, int parent, const PrimIndex& source) {
    auto& nodes = index.nodes_;
    const int base = static_cast<int>(nodes.size());
    const LayerOffset toStage = nodes[parent].offset;  // the source shares the parent's layer stack
    for (const IndexNode& from : source.nodes_) {
        IndexNode& node = nodes.emplace_back(from);
        node.offset = toStage.after(from.offset);
        node.parent = from.parent < 0 ? parent : from.parent + base;
        if (node.origin >= 0) node.origin += base;
        for (int& c : node.children) c += base;
    }
    // The source's own site becomes the relocate node: the identity map, no opinions of its own.
    IndexNode& relocate = nodes[base];
    relocate.arc = ArcType::Relocate;
    relocate.mapToParent = nullptr;
    relocate.namespaceDepth = pathDepth(nodes[parent].path);
    relocate.siblingNumber = 0;
    relocate.inert = true;
    relocate.specs.clear();
    nodesMade_ += source.nodes_.size();
    insertChild(index, base);
    return base;
}

void PrimIndexer::elideRelocationSources(PrimIndex& index, int n) const {
    for (int c : index.nodes_[n].children) {
        const IndexNode& child = index.nodes_[c];
        if (child.arc == ArcType::Relocate || child.inert) continue;
        if (child.stack->relocates.bySource(child.path))
            elide(index.nodes_, c);
        else
            elideRelocationSources(index, c);
    }
}

}  // namespace fluence::usd::detail
