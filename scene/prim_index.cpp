#include "scene/prim_index.h"

#include <algorithm>
#include <cstdio>
#include <deque>
#include <filesystem>
#include <functional>

#include "scene/asset_path.h"
#include "scene/list_op.h"

namespace fluence::usd::detail {

namespace {

const char* arcName(ArcType arc) {
    switch (arc) {
        case ArcType::Root: return "root";
        case ArcType::Inherit: return "inherit";
        case ArcType::Variant: return "variant";
        case ArcType::Relocate: return "relocate";
        case ArcType::Reference: return "reference";
        case ArcType::Payload: return "payload";
        default: return "specialize";
    }
}

std::string describeSite(const LayerStack& stack, const std::string& path) {
    std::string site = "@";
    site.append(std::filesystem::path(stack.identifier).filename().string()).append("@<").append(path).append(">");
    return site;
}

// Sibling strength (see the file comment of prim_index.h): true when a is stronger than b.
bool strongerSibling(const IndexNode& a, const IndexNode& b) {
    if (a.arc != b.arc) return a.arc < b.arc;
    if (a.namespaceDepth != b.namespaceDepth) return a.namespaceDepth > b.namespaceDepth;
    if (a.impliedRank != b.impliedRank) return a.impliedRank < b.impliedRank;
    return a.siblingNumber < b.siblingNumber;
}

bool sameSite(const IndexNode& node, const LayerStack* stack, const std::string& path) {
    return node.stack == stack && node.path == path;
}

}  // namespace

// ---- PrimIndex ---------------------------------------------------------------------------------

std::vector<int> PrimIndex::strengthOrder() const {
    std::vector<int> order;
    order.reserve(nodes_.size());
    std::vector<int> specializes;  // subtree roots, deferred to the end
    std::function<void(int)> visit = [&](int n) {
        order.push_back(n);
        for (int c : nodes_[n].children) {
            if (nodes_[c].arc == ArcType::Specialize)
                specializes.push_back(c);
            else
                visit(c);
        }
    };
    visit(0);
    auto originRoot = [&](int n) {
        while (nodes_[n].origin >= 0) n = nodes_[n].origin;
        return n;
    };
    auto treeDepth = [&](int n) {
        int depth = 0;
        for (; nodes_[n].parent >= 0; n = nodes_[n].parent) ++depth;
        return depth;
    };
    for (std::size_t done = 0; done < specializes.size();) {
        std::vector<int> batch(specializes.begin() + static_cast<std::ptrdiff_t>(done), specializes.end());
        done = specializes.size();
        // Group by the authored arc each node was implied from (in encounter order); within a
        // group the node nearest the root (the most local opinion) first.
        auto position = [&](int n) {
            auto it = std::find(batch.begin(), batch.end(), originRoot(n));
            return it == batch.end() ? std::find(batch.begin(), batch.end(), n) - batch.begin() : it - batch.begin();
        };
        std::stable_sort(batch.begin(), batch.end(), [&](int a, int b) {
            auto pa = position(a), pb = position(b);
            return pa != pb ? pa < pb : treeDepth(a) < treeDepth(b);
        });
        for (int n : batch) visit(n);
    }
    return order;
}

std::string PrimIndex::mapToRoot(int node, std::string path) const {
    for (int n = node; n > 0; n = nodes_[n].parent) path = mapToParent(n, std::move(path));
    return path;
}

std::string PrimIndex::mapToParent(int node, std::string path) const {
    const IndexNode& from = nodes_[node];
    if (!from.mapToParent) return path;
    return nodes_[from.parent].stack->relocates.apply(from.mapToParent->map(path));
}

std::string PrimIndex::instanceKey() const {
    std::string key;
    for (int n : strengthOrder()) {
        if (n == 0) continue;
        const IndexNode& node = nodes_[n];
        key += std::string(arcName(node.arc)) + " @" + node.stack->identifier + "@<" + node.path + ">";
        if (!node.offset.isIdentity()) {
            char offset[64];
            std::snprintf(offset, sizeof offset, "(offset=%.17g;scale=%.17g)", node.offset.offset, node.offset.scale);
            key += offset;
        }
        key += "\n";
    }
    return key;
}

// ---- PrimIndexer -------------------------------------------------------------------------------

struct PrimIndexer::Work {
    std::deque<int> arcs;        // nodes whose inherits, references, payloads, specializes are due
    std::vector<char> variants;  // per node: its variant sets are due
    std::size_t variantsDue = 0;
    bool overflowReported = false;

    void add(int node) {
        arcs.push_back(node);
        if (variants.size() <= static_cast<std::size_t>(node)) variants.resize(static_cast<std::size_t>(node) + 1, 0);
        variants[static_cast<std::size_t>(node)] = 1;
        ++variantsDue;
    }
};

// One entry of a composed arc list (references, payloads, inherits, specializes).
struct PrimIndexer::ArcItem {
    std::string asset;  // empty for internal references and class arcs
    std::string path;   // absolute prim path, or empty (a reference to the default prim)
    LayerOffset offset;
    int layer = 0;  // the authoring layer, in the node's layer stack
    SourceLocation location;

    bool operator==(const ArcItem& o) const {
        return asset == o.asset && path == o.path && offset.offset == o.offset.offset && offset.scale == o.offset.scale;
    }
};

std::vector<std::pair<int, SpecRef>> PrimIndexer::specsAt(const LayerStack& stack, const std::string& path) const {
    std::vector<std::pair<int, SpecRef>> specs;
    for (std::size_t i = 0; i < stack.layers.size(); ++i)
        if (SpecRef spec = stack.layers[i].specs->find(path)) specs.emplace_back(static_cast<int>(i), spec);
    return specs;
}

PrimIndex PrimIndexer::root(const LayerStack& stack, const std::string& path) {
    PrimIndex index;
    index.path_ = path;
    IndexNode root;
    root.stack = &stack;
    root.path = path;
    root.specs = specsAt(stack, path);
    index.nodes_.push_back(std::move(root));
    ++nodesMade_;
    Work work;
    work.add(0);
    finish(index, work);
    return index;
}

PrimIndex PrimIndexer::child(const PrimIndex& parent, const std::string& name, bool belowInstance) {
    PrimIndex index;
    index.path_ = childPrimPath(parent.path_, name);
    index.impliedCount_ = parent.impliedCount_;
    index.nodes_.reserve(parent.nodes_.size());
    Work work;
    for (const IndexNode& from : parent.nodes_) {
        IndexNode& node = index.nodes_.emplace_back();
        node.stack = from.stack;
        node.path = childPrimPath(from.path, name);
        node.arc = from.arc;
        node.parent = from.parent;
        node.children = from.children;
        node.mapToParent = from.mapToParent;
        node.offset = from.offset;
        node.namespaceDepth = from.namespaceDepth;
        node.siblingNumber = from.siblingNumber;
        node.impliedRank = from.impliedRank;
        node.origin = from.origin;
        node.inert = from.inert;
        if (!from.inert && (from.parent >= 0 || !belowInstance)) node.specs = specsAt(*node.stack, node.path);
        work.add(static_cast<int>(index.nodes_.size() - 1));
    }
    nodesMade_ += index.nodes_.size();
    finish(index, work);
    return index;
}

void PrimIndexer::finish(PrimIndex& index, Work& work) {
    orderFor_ = nullptr;  // a new index may sit where the last one was
    expand(index, work);
    orderFor_ = nullptr;
    checkOptionSelections(index);
    cull(index);
}

void PrimIndexer::expand(PrimIndex& index, Work& work) {
    while (true) {
        while (!work.arcs.empty()) {
            int n = work.arcs.front();
            work.arcs.pop_front();
            addArcs(index, n, work);
        }
        if (work.variantsDue == 0) return;
        // The strongest node still waiting for its variant sets.
        const std::vector<int>& order = orderOf(index);
        // (Nodes grafted by relocation arcs were expanded in their own index.)
        auto next = std::find_if(order.begin(), order.end(), [&](int n) {
            return static_cast<std::size_t>(n) < work.variants.size() && work.variants[n] != 0;
        });
        int n = *next;
        work.variants[n] = 0;
        --work.variantsDue;
        addVariants(index, n, work);
    }
}

bool PrimIndexer::overflows(const PrimIndex& index, std::size_t adding, const SourceLocation& where, Work& work) {
    if (index.nodes_.size() + adding <= kMaxNodesPerPrim) return false;
    if (!work.overflowReported)
        log_.warn("more than " + std::to_string(kMaxNodesPerPrim) +
                      " composition arcs contribute to this prim; the weaker ones are left out",
                  where, index.path_);
    work.overflowReported = true;
    return true;
}

int PrimIndexer::addNode(PrimIndex& index, IndexNode node, bool checkCycle, const SourceLocation& where, Work& work) {
    auto& nodes = index.nodes_;
    if (overflows(index, 1, where, work)) return -1;
    for (int sibling : nodes[node.parent].children)
        if (sameSite(nodes[sibling], node.stack, node.path) && nodes[sibling].arc == node.arc) return -1;
    if (checkCycle) {
        std::string path = stripVariantSelections(node.path);
        for (int a = node.parent; a >= 0; a = nodes[a].parent) {
            std::string ancestor = stripVariantSelections(nodes[a].path);
            if (nodes[a].stack != node.stack || !(hasPathPrefix(path, ancestor) || hasPathPrefix(ancestor, path)))
                continue;
            std::vector<std::string> chain;
            for (int c = node.parent;; c = nodes[c].parent) {
                chain.push_back(describeSite(*nodes[c].stack, nodes[c].path));
                if (c == a) break;
            }
            std::string cycle;
            for (auto it = chain.rbegin(); it != chain.rend(); ++it) cycle += *it + " -> ";
            log_.warn(std::string(arcName(node.arc)) + " cycle: " + cycle + describeSite(*node.stack, node.path) +
                          " (arc ignored)",
                      where, index.path_);
            return -1;
        }
    }
    node.specs = specsAt(*node.stack, node.path);
    int id = static_cast<int>(nodes.size());
    nodes.push_back(std::move(node));
    ++nodesMade_;
    insertChild(index, id);
    work.add(id);
    return id;
}

void PrimIndexer::insertChild(PrimIndex& index, int id) {
    auto& nodes = index.nodes_;
    auto& siblings = nodes[nodes[id].parent].children;
    auto at =
        std::find_if(siblings.begin(), siblings.end(), [&](int s) { return strongerSibling(nodes[id], nodes[s]); });
    siblings.insert(at, id);
}

std::vector<PrimIndexer::ArcItem> PrimIndexer::composeArcs(const IndexNode& node,
                                                           std::initializer_list<const char*> keys) const {
    std::string owner = stripVariantSelections(node.path);
    std::vector<SpecListEdits<ArcItem>> edits;
    for (const auto& layerAndSpec : node.specs) {
        // Named locals rather than a structured binding: clang before 16 cannot capture one in
        // the lambda below, and the fuzzer is built with clang.
        const auto& layer = layerAndSpec.first;
        const auto& spec = layerAndSpec.second;
        SpecListEdits<ArcItem> specEdits;
        for (const MetadataEntry& entry : spec.metadata()) {
            if (std::find_if(keys.begin(), keys.end(), [&](const char* k) { return entry.key == k; }) == keys.end())
                continue;
            ListEdit<ArcItem> edit{entry.op, {}};
            auto add = [&](const Value& v) {
                ArcItem item;
                item.layer = layer;
                item.location = entry.location;
                if (v.kind == ValueKind::Reference && v.strings.size() == 2) {
                    item.asset = v.strings[0];
                    bool defaultPrim = v.strings[1].empty() || v.strings[1] == "/";  // `</>`: the default prim
                    item.path = defaultPrim ? "" : absolutePath(owner, v.strings[1]);
                    item.offset = LayerOffset::of(v);
                    edit.items.push_back(std::move(item));
                } else if (v.kind == ValueKind::Path) {
                    for (const std::string& p : v.strings) {
                        item.path = absolutePath(owner, p);
                        edit.items.push_back(item);
                    }
                }
            };
            if (entry.value.kind == ValueKind::List)
                for (const Value& item : entry.value.items) add(item);
            else
                add(entry.value);
            specEdits.push_back(std::move(edit));
        }
        edits.push_back(std::move(specEdits));
    }
    return composeListEdits(edits, [](const ArcItem& a, const ArcItem& b) { return a == b; });
}

void PrimIndexer::addArcs(PrimIndex& index, int n, Work& work) {
    if (index.nodes_[n].inert) return;
    if (!index.nodes_[n].stack->relocates.empty()) addRelocation(index, n, work);
    if (index.nodes_[n].specs.empty()) return;
    const IndexNode& node = index.nodes_[n];
    std::vector<ArcItem> inherits = composeArcs(node, {"inherits"});
    std::vector<ArcItem> references = composeArcs(node, {"references"});
    std::vector<ArcItem> payloads = composeArcs(node, {"payload", "payloads"});
    std::vector<ArcItem> specializes = composeArcs(node, {"specializes"});
    for (std::size_t i = 0; i < inherits.size(); ++i)
        addClass(index, n, ArcType::Inherit, inherits[i], static_cast<int>(i), work);
    for (std::size_t i = 0; i < references.size(); ++i)
        addReference(index, n, ArcType::Reference, references[i], static_cast<int>(i), work);
    if (!payloads.empty() && !options_.loadRules.isLoaded(index.path_)) {
        index.unloadedPayload_ = true;
        payloads.clear();
    }
    for (std::size_t i = 0; i < payloads.size(); ++i)
        addReference(index, n, ArcType::Payload, payloads[i], static_cast<int>(i), work);
    for (std::size_t i = 0; i < specializes.size(); ++i)
        addClass(index, n, ArcType::Specialize, specializes[i], static_cast<int>(i), work);
}

void PrimIndexer::addReference(PrimIndex& index, int n, ArcType arc, const ArcItem& item, int sibling, Work& work) {
    const IndexNode& node = index.nodes_[n];
    const LayerStack::Entry& authoring = node.stack->layers[static_cast<std::size_t>(item.layer)];
    const LayerStack* stack = node.stack;
    std::string what = std::string(arcName(arc)) + " " + (item.asset.empty() ? "" : "@" + item.asset + "@") +
                       (item.path.empty() ? "" : "<" + item.path + ">");
    if (!item.asset.empty()) {
        ArcSite site{arcName(arc), arc == ArcType::Payload ? "payload" : "references", item.asset, item.location,
                     index.path_};
        stack = registry_.stackFor(anchorAssetPath(authoring.layer->identifier, item.asset), site);
        if (!stack) return;
    }
    std::string target = item.path.empty() ? stack->defaultPrimPath() : item.path;
    std::string layerName = std::filesystem::path(stack->identifier).filename().string();
    if (target.empty()) {
        log_.warn(what + " ignored: '" + layerName + "' has no defaultPrim", item.location, index.path_);
        return;
    }
    if (!stack->hasSpecAt(target)) {
        std::string missing =
            item.path.empty() ? "the defaultPrim of '" + layerName + "', <" + target + ">," : "<" + target + ">";
        log_.warn(
            what + " ignored: " + missing + " does not exist" + (item.path.empty() ? "" : " in '" + layerName + "'"),
            item.location, index.path_);
        return;
    }
    IndexNode child;
    child.stack = stack;
    child.path = target;
    child.arc = arc;
    child.parent = n;
    child.mapToParent = std::make_shared<MapFunction>(target, stripVariantSelections(node.path));
    // An external arc also converts the target stack's time codes to the authoring layer's rate.
    LayerOffset rate = item.asset.empty()
                           ? LayerOffset{}
                           : LayerOffset::between(timeCodesPerSecond(*authoring.layer), stack->timeCodesPerSecond());
    child.offset = node.offset.after(authoring.offset).after(item.offset).after(rate);
    child.namespaceDepth = pathDepth(node.path);
    child.siblingNumber = sibling;
    addNode(index, std::move(child), true, item.location, work);
}

void PrimIndexer::addClass(PrimIndex& index, int n, ArcType arc, const ArcItem& item, int sibling, Work& work) {
    const IndexNode& node = index.nodes_[n];
    IndexNode child;
    child.stack = node.stack;
    child.path = item.path;
    child.arc = arc;
    child.parent = n;
    child.mapToParent = std::make_shared<MapFunction>(item.path, stripVariantSelections(node.path));
    child.offset = node.offset;
    child.namespaceDepth = pathDepth(node.path);
    child.siblingNumber = sibling;
    int id = addNode(index, std::move(child), true, item.location, work);
    if (id >= 0) implyClass(index, id, work);
}

void PrimIndexer::implyClass(PrimIndex& index, int classNode, Work& work) {
    auto& nodes = index.nodes_;
    std::string path = nodes[classNode].path;
    int origin = classNode;
    for (int from = nodes[classNode].parent; from > 0;) {
        int to = nodes[from].parent;
        path = index.mapToParent(from, path);
        const LayerStack* stack = nodes[to].stack;
        bool exists =
            std::any_of(nodes.begin(), nodes.end(), [&](const IndexNode& x) { return sameSite(x, stack, path); });
        if (!exists) {
            IndexNode implied;
            implied.stack = stack;
            implied.path = path;
            implied.arc = nodes[classNode].arc;
            implied.parent = to;
            implied.mapToParent = std::make_shared<MapFunction>(path, stripVariantSelections(nodes[to].path));
            implied.offset = nodes[to].offset;
            implied.namespaceDepth = nodes[classNode].namespaceDepth;
            implied.siblingNumber = nodes[classNode].siblingNumber;
            implied.impliedRank = ++index.impliedCount_;
            implied.origin = origin;
            int id = addNode(index, std::move(implied), false, {}, work);
            if (id < 0) return;
            origin = id;
        }
        from = to;
    }
}

const std::vector<int>& PrimIndexer::orderOf(const PrimIndex& index) {
    // Nodes are only ever added while an index grows, so its size tells whether the order is stale.
    if (orderFor_ != &index || orderSize_ != index.nodes_.size()) {
        order_ = index.strengthOrder();
        orderFor_ = &index;
        orderSize_ = index.nodes_.size();
    }
    return order_;
}

std::optional<std::string> PrimIndexer::selectionFor(const PrimIndex& index, const std::string& set) {
    for (auto it = options_.variantSelections.rbegin(); it != options_.variantSelections.rend(); ++it)
        if (it->primPath == index.path_ && it->variantSet == set) return it->selection;
    for (int n : orderOf(index)) {
        for (const auto& [layer, spec] : index.nodes_[n].specs) {
            const MetadataEntry* entry = findMetadata(spec.metadata(), "variants");
            if (!entry) continue;
            if (const Value* selection = entry->value.find(set)) return selection->asString().value_or("");
        }
    }
    return std::nullopt;
}

void PrimIndexer::addVariants(PrimIndex& index, int n, Work& work) {
    if (index.nodes_[n].specs.empty()) return;
    std::vector<SpecListEdits<std::string>> edits;
    std::vector<std::string> specified;  // sets with a variantSet block, when no list names any
    bool listed = false;
    for (const auto& [layer, spec] : index.nodes_[n].specs) {
        SpecListEdits<std::string> specEdits;
        for (const MetadataEntry& entry : spec.metadata()) {
            if (entry.key != "variantSets") continue;
            listed = true;
            std::vector<std::string> names =
                entry.value.isStringLike() ? entry.value.strings : std::vector<std::string>{};
            specEdits.push_back({entry.op, std::move(names)});
        }
        edits.push_back(std::move(specEdits));
        for (const VariantSetSpec& set : spec.variantSets()) {
            if (std::find(specified.begin(), specified.end(), set.name) == specified.end())
                specified.push_back(set.name);
            for (const VariantSpec& variant : set.variants) index.variantSets_[set.name].insert(variant.name);
        }
    }
    std::vector<std::string> sets = listed ? composeListEdits(edits, std::equal_to<>()) : specified;
    for (std::size_t i = 0; i < sets.size(); ++i) {
        index.variantSets_[sets[i]];  // a listed set counts as present even without variants
        std::optional<std::string> selection = selectionFor(index, sets[i]);
        if (!selection || selection->empty()) continue;
        const IndexNode& node = index.nodes_[n];
        std::string path = node.path + "{" + sets[i] + "=" + *selection + "}";
        if (!node.stack->hasSpecAt(path)) continue;
        IndexNode variant;
        variant.stack = node.stack;
        variant.path = std::move(path);
        variant.arc = ArcType::Variant;
        variant.parent = n;
        variant.offset = node.offset;
        variant.namespaceDepth = pathDepth(node.path);
        variant.siblingNumber = static_cast<int>(i);
        addNode(index, std::move(variant), false, {}, work);
    }
}

void PrimIndexer::checkOptionSelections(const PrimIndex& index) {
    for (const VariantSelection& option : options_.variantSelections) {
        if (option.primPath != index.path_) continue;
        auto set = index.variantSets_.find(option.variantSet);
        std::string where = "variant selection " + option.variantSet + "=" + option.selection + " for <" +
                            option.primPath + "> ignored: ";
        if (set == index.variantSets_.end())
            log_.warn(where + "the prim has no variant set '" + option.variantSet + "'", {}, index.path_);
        else if (!set->second.contains(option.selection))
            log_.warn(where + "variant set '" + option.variantSet + "' has no variant '" + option.selection + "'", {},
                      index.path_);
    }
}

void PrimIndexer::cull(PrimIndex& index) const {
    auto& nodes = index.nodes_;
    std::vector<char> keep(nodes.size(), 0);
    std::function<bool(int)> mark = [&](int n) {
        bool any = !nodes[n].specs.empty() || n == 0;
        for (int c : nodes[n].children) any = mark(c) || any;
        keep[n] = any;
        return any;
    };
    mark(0);
    if (std::all_of(keep.begin(), keep.end(), [](char k) { return k; })) return;
    std::vector<int> renumber(nodes.size(), -1);
    std::vector<IndexNode> kept;
    for (std::size_t n = 0; n < nodes.size(); ++n) {
        if (!keep[n]) continue;
        renumber[n] = static_cast<int>(kept.size());
        kept.push_back(std::move(nodes[n]));
    }
    for (IndexNode& node : kept) {
        if (node.parent >= 0) node.parent = renumber[node.parent];
        if (node.origin >= 0) node.origin = renumber[node.origin];
        std::vector<int> children;
        for (int c : node.children)
            if (renumber[c] >= 0) children.push_back(renumber[c]);
        node.children = std::move(children);
    }
    nodes = std::move(kept);
}

}  // namespace fluence::usd::detail
