#include "apps/cryptomatte_layers.h"

#include <algorithm>

#include "apps/cli_options.h"
#include "core/name_table.h"
#include "delegate/prim_reader.h"
#include "output/cryptomatte.h"

namespace fluence::app {

namespace {

struct SourceName {
    const char* option;      // in --cryptomatte
    const char* sourceName;  // a RenderVar's sourceName, and the CLI layer's type name
    CryptomatteSource source;
};
constexpr SourceName kSources[] = {{"object", "CryptoObject", CryptomatteSource::Object},
                                   {"material", "CryptoMaterial", CryptomatteSource::Material}};

}  // namespace

std::vector<CryptomatteSource> parseCryptomatteOption(const std::vector<std::string>& items) {
    if (items.empty()) throw UsageError("--cryptomatte expects a list of layers: object, material");
    std::vector<CryptomatteSource> sources;
    for (const std::string& item : items) {
        const auto* found = std::find_if(std::begin(kSources), std::end(kSources),
                                         [&](const SourceName& s) { return item == s.option; });
        if (found == std::end(kSources))
            throw UsageError("--cryptomatte: '" + item + "' is not a layer (object, material)");
        if (std::find(sources.begin(), sources.end(), found->source) == sources.end()) sources.push_back(found->source);
    }
    return sources;
}

std::vector<CryptomatteLayerRequest> cryptomatteLayers(const delegate::RenderProductDesc* product,
                                                       const std::vector<CryptomatteSource>& options) {
    std::vector<CryptomatteLayerRequest> layers;
    auto named = [&](const std::string& name) {
        return std::any_of(layers.begin(), layers.end(),
                           [&](const CryptomatteLayerRequest& l) { return l.typeName == name; });
    };
    if (product)
        for (const delegate::RenderVarDesc& var : product->vars) {
            if (var.sourceType != "raw") continue;
            const auto* found = std::find_if(std::begin(kSources), std::end(kSources),
                                             [&](const SourceName& s) { return var.sourceName == s.sourceName; });
            if (found == std::end(kSources)) continue;
            const std::string name = primName(var.path);
            if (named(name))
                throw delegate::SceneError("RenderVar " + var.path + ": a second Cryptomatte layer named '" + name +
                                           "'");
            layers.push_back({name, found->source});
        }
    for (CryptomatteSource source : options) {
        const auto* found = std::find_if(std::begin(kSources), std::end(kSources),
                                         [&](const SourceName& s) { return s.source == source; });
        if (!named(found->sourceName)) layers.push_back({found->sourceName, source});
    }
    return layers;
}

std::unique_ptr<CryptomatteFilm> cryptomatteFilm(const std::vector<CryptomatteLayerRequest>& layers, int width,
                                                 int height) {
    if (layers.empty()) return nullptr;
    std::vector<CryptomatteSource> sources;
    for (const CryptomatteLayerRequest& layer : layers) sources.push_back(layer.source);
    return std::make_unique<CryptomatteFilm>(width, height, std::move(sources));
}

void appendCryptomatteLayers(Image& image, output::ExrHeader& header, const CryptomatteFilm& film,
                             const std::vector<CryptomatteLayerRequest>& layers, const render::RenderScene& scene,
                             int depth) {
    std::vector<output::CryptomatteLayer> described;
    for (const CryptomatteLayerRequest& layer : layers)
        described.push_back({layer.typeName, layer.source == CryptomatteSource::Object ? &scene.objectNames()
                                                                                       : &scene.materialNames()});
    output::appendCryptomatte(image, header, film, described, depth);
}

}  // namespace fluence::app
