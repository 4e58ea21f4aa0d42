#include "scene/relocates.h"

#include <algorithm>
#include <functional>

#include "scene/namespace_remap.h"

namespace fluence::usd::detail {

namespace {

std::string parentOf(const std::string& path) {
    std::size_t slash = path.rfind('/');
    return slash == 0 || slash == std::string::npos ? "/" : path.substr(0, slash);
}

std::string nameOf(const std::string& path) { return path.substr(path.rfind('/') + 1); }

std::string describe(const Relocation& r) { return "relocate <" + r.source + "> -> <" + r.target + ">"; }

bool isPrimPath(const std::string& path) {
    return path.size() > 1 && path.front() == '/' && path.find_first_of(".{}") == std::string::npos;
}

// Why a relocation is invalid on its own ("" when it is valid).
std::string problemOf(const Relocation& r) {
    if (!isPrimPath(r.source) || (!r.target.empty() && !isPrimPath(r.target)))
        return "only prims can be relocated, by absolute paths without variant selections";
    if (parentOf(r.source) == "/") return "a root prim cannot be relocated";
    if (r.target.empty()) return "";
    if (r.target == r.source) return "the target is the source itself";
    if (hasPathPrefix(r.target, r.source)) return "the target cannot be a descendant of its source";
    if (hasPathPrefix(r.source, r.target)) return "the target cannot be an ancestor of its source";
    return "";
}

// The relocations of one layer, in authored order: its layer metadata, else its prims' metadata.
class LayerRelocates {
public:
    explicit LayerRelocates(std::vector<Relocation>& out) : out_(out) {}

    void read(const Layer& layer) {
        if (const MetadataEntry* entry = findMetadata(layer.metadata, "relocates")) {
            add(*entry, "/");
            return;
        }
        std::function<void(const PrimSpec&)> visit = [&](const PrimSpec& prim) {
            if (const MetadataEntry* entry = findMetadata(prim.metadata, "relocates")) add(*entry, prim.path);
            for (const auto& child : prim.children) visit(*child);
        };
        for (const auto& prim : layer.rootPrims) visit(*prim);
    }

private:
    void add(const MetadataEntry& entry, const std::string& anchor) {
        if (!entry.value.dictionary) return;
        for (const auto& [source, target] : *entry.value.dictionary) {
            std::string to = target.asString().value_or("");
            out_.push_back({absolutePath(anchor, source), to.empty() ? to : absolutePath(anchor, to), entry.location});
        }
    }

    std::vector<Relocation>& out_;
};

}  // namespace

Relocates Relocates::gather(const std::vector<const Layer*>& layers, CompositionLog& log) {
    std::vector<Relocation> authored;
    LayerRelocates reader(authored);
    for (const Layer* layer : layers) reader.read(*layer);

    // Each relocation on its own; the strongest relocation of a source wins.
    std::vector<Relocation> candidates;
    std::set<std::string> sources;
    for (Relocation& r : authored) {
        if (std::string problem = problemOf(r); !problem.empty())
            log.warn(describe(r) + " ignored: " + problem, r.location, r.source);
        else if (sources.insert(r.source).second)
            candidates.push_back(std::move(r));
    }

    // Against each other.
    std::map<std::string, std::size_t> source;
    std::map<std::string, std::vector<std::size_t>> target;
    for (std::size_t i = 0; i < candidates.size(); ++i) {
        source[candidates[i].source] = i;
        if (!candidates[i].target.empty()) target[candidates[i].target].push_back(i);
    }
    std::vector<std::string> problems(candidates.size());
    auto reject = [&](std::size_t i, const std::string& problem) {
        if (problems[i].empty()) problems[i] = problem;
    };
    for (const auto& [path, movers] : target)
        if (movers.size() > 1)
            for (std::size_t i : movers) reject(i, "another relocation moves a prim to the same target");
    for (std::size_t i = 0; i < candidates.size(); ++i) {
        const Relocation& r = candidates[i];
        if (auto other = source.find(r.target); other != source.end()) {
            reject(i, "the target is the source of relocate <" + r.target + ">");
            reject(other->second, "the source is the target of relocate <" + r.source + ">");
        }
        for (std::string p = parentOf(r.target); !r.target.empty() && p != "/"; p = parentOf(p))
            if (source.contains(p)) reject(i, "the target lies below <" + p + ">, which is itself relocated");
        for (std::string p = parentOf(r.source); p != "/"; p = parentOf(p))
            if (source.contains(p)) reject(i, "the source lies below <" + p + ">, which is itself relocated");
    }

    Relocates out;
    for (std::size_t i = 0; i < candidates.size(); ++i) {
        const Relocation& r = candidates[i];
        if (!problems[i].empty()) {
            log.warn(describe(r) + " ignored: " + problems[i], r.location, r.source);
            continue;
        }
        std::size_t at = out.relocations_.size();
        out.bySource_[r.source] = at;
        out.byParent_[parentOf(r.source)].push_back(at);
        if (!r.target.empty()) {
            out.byTarget_[r.target] = at;
            if (parentOf(r.target) != parentOf(r.source)) out.byParent_[parentOf(r.target)].push_back(at);
        }
        out.relocations_.push_back(std::move(candidates[i]));
    }
    return out;
}

const Relocation* Relocates::bySource(const std::string& path) const {
    auto it = bySource_.find(path);
    return it == bySource_.end() ? nullptr : &relocations_[it->second];
}

const Relocation* Relocates::byTarget(const std::string& path) const {
    auto it = byTarget_.find(path);
    return it == byTarget_.end() ? nullptr : &relocations_[it->second];
}

std::string Relocates::apply(std::string path) const {
    for (std::size_t step = 0; step <= relocations_.size(); ++step) {
        const Relocation* closest = nullptr;
        for (std::string p = path.substr(0, path.find('.')); !closest && p.size() > 1; p = parentOf(p))
            closest = bySource(p);
        if (!closest || closest->target.empty()) break;
        path = closest->target + path.substr(closest->source.size());
    }
    return path;
}

bool Relocates::editChildNames(const std::string& parent, std::vector<std::string>& names,
                               std::set<std::string>& prohibited) const {
    auto here = byParent_.find(parent);
    if (here == byParent_.end()) return false;
    auto has = [&](const std::string& name) { return std::find(names.begin(), names.end(), name) != names.end(); };
    bool changed = false;
    std::vector<std::string> arriving;
    for (std::size_t i : here->second) {
        const Relocation& r = relocations_[i];
        bool fromHere = parentOf(r.source) == parent;
        bool toHere = !r.target.empty() && parentOf(r.target) == parent;
        if (fromHere) {
            prohibited.insert(nameOf(r.source));
            auto at = std::find(names.begin(), names.end(), nameOf(r.source));
            if (at == names.end()) continue;
            changed = true;
            if (toHere && !has(nameOf(r.target)))
                *at = nameOf(r.target);  // a rename keeps the child's place
            else
                names.erase(at);
        } else if (toHere && !has(nameOf(r.target))) {
            arriving.push_back(nameOf(r.target));
        }
    }
    std::sort(arriving.begin(), arriving.end());
    names.insert(names.end(), arriving.begin(), arriving.end());
    return changed || !arriving.empty();
}

}  // namespace fluence::usd::detail
