#include "scene/layer_stack.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>

#include "scene/asset_path.h"
#include "scene/crate_reader.h"
#include "scene/layer_file.h"
#include "scene/namespace_remap.h"
#include "scene/usda_parser.h"
#include "scene/usdz_package.h"

namespace fluence::usd::detail {

namespace fs = std::filesystem;

LayerOffset LayerOffset::of(const Value& arc) {
    if (arc.kind != ValueKind::Reference || arc.numbers.size() < 2) return {};
    return {arc.numbers[0], arc.numbers[1]};
}

double timeCodesPerSecond(const Layer& layer) {
    for (const char* key : {"timeCodesPerSecond", "framesPerSecond"}) {
        const MetadataEntry* entry = findMetadata(layer.metadata, key);
        std::optional<double> rate = entry ? entry->value.asDouble() : std::nullopt;
        if (rate && std::isfinite(*rate) && *rate > 0.0) return *rate;
    }
    return 24.0;
}

// ---- SpecIndex ---------------------------------------------------------------------------------

namespace {

class SpecIndexBuilder {
public:
    explicit SpecIndexBuilder(std::unordered_map<std::string, SpecRef>& specs) : specs_(specs) {}

    void prim(const PrimSpec& spec, const std::string& path) {
        specs_.emplace(path, SpecRef{&spec, nullptr});
        for (const auto& child : spec.children) prim(*child, childPrimPath(path, child->name));
        variantSets(spec.variantSets, path);
    }

    void variantSets(const std::vector<VariantSetSpec>& sets, const std::string& owner) {
        for (const VariantSetSpec& set : sets) {
            for (const VariantSpec& variant : set.variants) {
                std::string path = owner + "{" + set.name + "=" + variant.name + "}";
                specs_.emplace(path, SpecRef{nullptr, &variant});
                for (const auto& child : variant.children) prim(*child, childPrimPath(path, child->name));
                variantSets(variant.variantSets, path);
            }
        }
    }

private:
    std::unordered_map<std::string, SpecRef>& specs_;
};

}  // namespace

SpecIndex::SpecIndex(const Layer& layer) {
    SpecIndexBuilder builder(specs_);
    for (const auto& prim : layer.rootPrims) builder.prim(*prim, childPrimPath("/", prim->name));
}

SpecRef SpecIndex::find(const std::string& path) const {
    auto it = specs_.find(path);
    return it == specs_.end() ? SpecRef{} : it->second;
}

// ---- LayerStack --------------------------------------------------------------------------------

std::string LayerStack::defaultPrimPath() const {
    const MetadataEntry* entry = findMetadata(rootLayer().metadata, "defaultPrim");
    std::string name = entry ? entry->value.asString().value_or("") : "";
    if (name.empty() || name.front() == '/') return name;
    return "/" + name;
}

bool LayerStack::hasSpecAt(const std::string& path) const {
    return std::any_of(layers.begin(), layers.end(), [&](const Entry& e) { return bool(e.specs->find(path)); });
}

// ---- LayerRegistry -----------------------------------------------------------------------------

namespace {

std::string lowercaseExtension(const std::string& path) {
    std::string extension = fs::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension;
}

std::string firstBytes(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    char bytes[8] = {};
    file.read(bytes, sizeof bytes);
    return std::string(bytes, static_cast<std::size_t>(file.gcount()));
}

// Why the file at `path` cannot be read as a USD text layer ("" when it can be tried).
std::string unusableLayerProblem(const std::string& path) {
    if (!missingFormatPlugin(path).empty()) return unsupportedFormatMessage(path);
    std::error_code error;
    if (splitPackagePath(path)) {
        if (std::string problem = packagedEntryProblem(path); !problem.empty()) return problem;
    } else if (!fs::is_regular_file(path, error)) {
        return "cannot find '" + path + "'";
    }
    std::string start = firstBytes(path);
    if (isCrateHeader(start) || isMaterialXPath(path) || isUsdzPath(path) || splitPackagePath(path)) return "";
    std::string extension = lowercaseExtension(path);
    bool textHeader = start.rfind("#usda", 0) == 0 || start.rfind("#sdf", 0) == 0;
    if (!textHeader && extension != ".usda" && extension != ".usd" && extension != ".sdf")
        return "'" + path + "' is not a USD layer (the '" + extension + "' file format is not supported)";
    return "";
}

}  // namespace

const Layer& LayerRegistry::keep(std::unique_ptr<Layer> layer) {
    for (const ParseWarning& w : layer->warnings) log_.warn(w.message, w.location, "");
    layers_.push_back(std::move(layer));
    return *layers_.back();
}

const LayerStack& LayerRegistry::openRoot(const std::string& path) {
    std::unique_ptr<Layer> layer = readLayerFile(path);
    std::string absolute = normalizedAbsolutePath(path);
    byPath_[absolute] = layer.get();
    files_.push_back(absolute);
    return buildStack(keep(std::move(layer)));
}

const LayerStack& LayerRegistry::adoptRoot(std::unique_ptr<Layer> layer) {
    byPath_[normalizedAbsolutePath(layer->identifier)] = layer.get();
    files_.push_back(layer->identifier);
    return buildStack(keep(std::move(layer)));
}

const LayerStack* LayerRegistry::stackFor(const std::string& resolvedPath, const ArcSite& site) {
    const Layer* layer = layerFor(resolvedPath, site);
    return layer ? &buildStack(*layer) : nullptr;
}

std::vector<std::string> LayerRegistry::files() const { return files_; }

const Layer* LayerRegistry::layerFor(const std::string& resolvedPath, const ArcSite& site) {
    auto cached = byPath_.find(resolvedPath);
    std::string problem;
    if (cached != byPath_.end()) {
        if (cached->second) return cached->second;
        problem = problems_[resolvedPath];
    } else {
        problem = unusableLayerProblem(resolvedPath);
        if (problem.empty()) {
            files_.push_back(resolvedPath);
            return byPath_[resolvedPath] = &keep(readLayerFile(resolvedPath));
        }
        byPath_[resolvedPath] = nullptr;
        problems_[resolvedPath] = problem;
    }
    log_.warnAboutAsset(resolvedPath, std::string(site.arc) + " @" + site.authored + "@ ignored: " + problem,
                        site.location, site.primPath);
    std::error_code error;
    log_.unresolvedArc({site.primPath, site.property, site.authored, resolvedPath,
                        fs::is_regular_file(resolvedPath, error), site.location});
    return nullptr;
}

const SpecIndex& LayerRegistry::specIndexOf(const Layer& layer) {
    auto& index = specIndexes_[&layer];
    if (!index) {
        index = std::make_unique<SpecIndex>(layer);
        specCount_ += index->size();
    }
    return *index;
}

const LayerStack& LayerRegistry::buildStack(const Layer& root) {
    auto& stack = stacks_[&root];
    if (stack) return *stack;
    stack = std::make_unique<LayerStack>();
    stack->identifier = root.identifier;
    std::vector<std::string> chain = {normalizedAbsolutePath(root.identifier)};
    addToStack(*stack, root, {}, chain);
    std::vector<const Layer*> layers;
    for (const LayerStack::Entry& entry : stack->layers) layers.push_back(entry.layer);
    stack->relocates = Relocates::gather(layers, log_);
    return *stack;
}

void LayerRegistry::addToStack(LayerStack& stack, const Layer& layer, const LayerOffset& offset,
                               std::vector<std::string>& chain) {
    bool present = std::any_of(stack.layers.begin(), stack.layers.end(),
                               [&](const LayerStack::Entry& e) { return e.layer == &layer; });
    if (present) return;
    stack.layers.push_back({&layer, &specIndexOf(layer), offset});
    const MetadataEntry* subLayers = findMetadata(layer.metadata, "subLayers");
    if (!subLayers) return;
    for (const Value& item : subLayers->value.items) {
        if (item.kind != ValueKind::Reference || item.strings.empty()) continue;
        const std::string& authored = item.strings[0];
        std::string resolved = anchorAssetPath(layer.identifier, authored);
        auto repeat = std::find(chain.begin(), chain.end(), resolved);
        if (repeat != chain.end()) {
            std::string cycle;
            for (auto it = repeat; it != chain.end(); ++it) cycle += fs::path(*it).filename().string() + " -> ";
            log_.warn(
                "sublayer cycle: " + cycle + fs::path(resolved).filename().string() + " (@" + authored + "@ ignored)",
                subLayers->location, "");
            continue;
        }
        const Layer* sub = layerFor(resolved, {"sublayer", "subLayers", authored, subLayers->location, ""});
        if (!sub) continue;
        chain.push_back(resolved);
        LayerOffset rate = LayerOffset::between(timeCodesPerSecond(layer), timeCodesPerSecond(*sub));
        addToStack(stack, *sub, offset.after(LayerOffset::of(item).after(rate)), chain);
        chain.pop_back();
    }
}

}  // namespace fluence::usd::detail
