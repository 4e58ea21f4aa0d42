#include "scene/stage.h"

#include <algorithm>
#include <map>

#include "scene/asset_path.h"
#include "scene/flatten.h"
#include "scene/layer_stack.h"
#include "scene/namespace_remap.h"
#include "scene/stage_metadata.h"
#include "scene/time_samples.h"

namespace fluence::usd {

Stage::Stage(std::unique_ptr<Layer> rootLayer, const StageOptions& options) : options_(options) {
    compose(std::move(rootLayer), "");
}

Stage::Stage(const OpenFile& file, const StageOptions& options) : options_(options) { compose(nullptr, file.path); }

Stage::~Stage() = default;

std::unique_ptr<Stage> Stage::open(const std::string& path, const StageOptions& options) {
    return std::unique_ptr<Stage>(new Stage(OpenFile{path}, options));
}

void Stage::compose(std::unique_ptr<Layer> inMemoryRoot, const std::string& path) {
    registry_ = std::make_unique<detail::LayerRegistry>(log_);
    rootStack_ = inMemoryRoot ? &registry_->adoptRoot(std::move(inMemoryRoot)) : &registry_->openRoot(path);
    detail::checkStageMetadata(rootStack_->rootLayer(), log_);
    detail::FlattenResult result = detail::flatten(*rootStack_, *registry_, log_, options_);
    composed_ = std::move(result.layer);
    layerFiles_ = registry_->files();
    addAssets(std::move(result.assets));
    for (auto& prim : composed_->rootPrims) addPrims(*prim);
}

const Layer& Stage::rootLayer() const { return rootStack_->rootLayer(); }

void Stage::addPrims(PrimSpec& prim) {
    primsByPath_[prim.path] = &prim;
    for (auto& child : prim.children) addPrims(*child);
}

void Stage::removePrims(const PrimSpec& prim) {
    primsByPath_.erase(prim.path);
    for (const auto& child : prim.children) removePrims(*child);
}

void Stage::addAssets(std::vector<AssetReference> assets) {
    std::map<std::string, bool> exists;
    for (AssetReference& asset : assets) {
        auto [it, added] = exists.try_emplace(asset.resolved, false);
        if (added) it->second = assetExists(asset.resolved);
        asset.exists = it->second;
        assets_.push_back(std::move(asset));
    }
}

std::vector<AssetReference> Stage::assetReferences() const {
    std::vector<AssetReference> all = assets_;
    all.insert(all.end(), log_.unresolvedArcs().begin(), log_.unresolvedArcs().end());
    return all;
}

const PrimSpec* Stage::prim(const std::string& path) const {
    auto it = primsByPath_.find(path);
    return it == primsByPath_.end() ? nullptr : it->second;
}

void Stage::applyEdit(PrimSpec& prim, const AttributeEdit& edit) {
    auto it = std::find_if(prim.attributes.begin(), prim.attributes.end(),
                           [&](const AttributeSpec& a) { return a.name == edit.name; });
    if (it == prim.attributes.end()) {
        AttributeSpec& added = prim.attributes.emplace_back();
        added.name = edit.name;
        added.typeName = edit.value.typeName;
        added.location = prim.location;
        it = prim.attributes.end() - 1;
    }
    it->hasDefault = true;
    it->defaultValue = edit.value;
    it->timeSamples.clear();
}

bool Stage::setAttribute(const std::string& primPath, const std::string& name, const Value& value) {
    auto found = primsByPath_.find(primPath);
    if (found == primsByPath_.end()) return false;
    AttributeEdit edit{primPath, name, value};
    applyEdit(*found->second, edit);
    std::erase_if(edits_, [&](const AttributeEdit& e) { return e.primPath == primPath && e.name == name; });
    edits_.push_back(std::move(edit));
    return true;
}

void Stage::setVariantSelection(const std::string& primPath, const std::string& variantSet,
                                const std::string& selection) {
    std::erase_if(options_.variantSelections,
                  [&](const VariantSelection& v) { return v.primPath == primPath && v.variantSet == variantSet; });
    options_.variantSelections.push_back({primPath, variantSet, selection});
    auto found = primsByPath_.find(primPath);
    if (found == primsByPath_.end()) return;

    detail::FlattenedPrim fresh = detail::flattenSubtree(*rootStack_, primPath, *registry_, log_, options_);
    std::size_t slash = primPath.rfind('/');
    auto& siblings = slash == 0 ? composed_->rootPrims : primsByPath_.at(primPath.substr(0, slash))->children;
    auto slot = std::find_if(siblings.begin(), siblings.end(), [&](const auto& p) { return p.get() == found->second; });
    removePrims(**slot);
    std::erase_if(assets_, [&](const AssetReference& a) { return detail::hasPathPrefix(a.primPath, primPath); });
    if (!fresh.prim) {
        siblings.erase(slot);
        return;
    }
    *slot = std::move(fresh.prim);
    addPrims(**slot);
    addAssets(std::move(fresh.assets));
    for (const AttributeEdit& edit : edits_)
        if (detail::hasPathPrefix(edit.primPath, primPath))
            if (auto it = primsByPath_.find(edit.primPath); it != primsByPath_.end()) applyEdit(*it->second, edit);
}

namespace {

std::optional<std::string> stringMetadata(const Layer& layer, const char* key) {
    const MetadataEntry* e = findMetadata(layer.metadata, key);
    return e ? e->value.asString() : std::nullopt;
}

std::optional<double> numberMetadata(const Layer& layer, const char* key) {
    const MetadataEntry* e = findMetadata(layer.metadata, key);
    return e ? e->value.asDouble() : std::nullopt;
}

bool isActive(const PrimSpec& prim) {
    const MetadataEntry* e = findMetadata(prim.metadata, "active");
    if (!e) return true;
    if (auto b = e->value.asDouble()) return *b != 0.0;
    return e->value.asString().value_or("true") != "false";
}

void visitPrim(const PrimSpec& prim, const std::function<bool(const PrimSpec&)>& visit) {
    if (prim.specifier != Specifier::Def || !isActive(prim)) return;
    if (visit(prim))
        for (const auto& child : prim.children) visitPrim(*child, visit);
}

}  // namespace

std::string Stage::defaultPrim() const { return stringMetadata(*composed_, "defaultPrim").value_or(""); }

char Stage::upAxis() const { return stringMetadata(*composed_, "upAxis").value_or("Y") == "Z" ? 'Z' : 'Y'; }

double Stage::metersPerUnit() const { return numberMetadata(*composed_, "metersPerUnit").value_or(0.01); }

std::optional<double> Stage::startTimeCode() const { return numberMetadata(*composed_, "startTimeCode"); }

std::optional<double> Stage::endTimeCode() const { return numberMetadata(*composed_, "endTimeCode"); }

void Stage::traverse(const std::function<bool(const PrimSpec&)>& visit) const {
    for (const auto& prim : composed_->rootPrims) visitPrim(*prim, visit);
}

void Stage::traverse(const PrimSpec& root, const std::function<bool(const PrimSpec&)>& visit) {
    visitPrim(root, visit);
}

std::optional<Value> Stage::resolve(const AttributeSpec& attribute, double time) {
    bool fromDefault = std::isnan(time) || attribute.timeSamples.empty();
    if (fromDefault && !attribute.hasDefault) return std::nullopt;
    Value value = fromDefault ? attribute.defaultValue : valueAtTime(attribute.timeSamples, time);
    if (value.isBlocked()) return std::nullopt;
    return value;
}

}  // namespace fluence::usd
