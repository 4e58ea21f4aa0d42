#include "apps/render_fingerprint.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>

#include "core/fnv_hash.h"
#include "scene/usdz_package.h"
#include "version.h"

namespace fluence::app {

namespace {

// Numbers as text that reads back exactly.
std::string exact(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", value);
    return text;
}

// FNV-1a over every layer file's path and bytes, as 16 hex digits. A layer inside a USDZ package
// ("pkg.usdz[scene.usdc]") is hashed as its package file.
std::string hex(std::uint64_t hash) {
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
    return text;
}

// The file on disk that holds `path`: a USDZ entry's package ("pkg.usdz[scene.usdc]"), else itself.
std::string fileOnDisk(const std::string& path) {
    const std::optional<usd::PackagePath> packaged = usd::splitPackagePath(path);
    return packaged ? packaged->package : path;
}

std::string layerFilesHash(const usd::Stage& stage) {
    std::uint64_t hash = kFnv1aOffsetBasis;
    for (const std::string& file : stage.layerFiles()) {
        hash = fnv1a(file, hash);
        std::ifstream in(fileOnDisk(file), std::ios::binary);
        std::ostringstream bytes;
        bytes << in.rdbuf();
        hash = fnv1a(bytes.str(), fnv1a(std::string_view("\0", 1), hash));
    }
    return hex(hash);
}

// The asset files the stage refers to (textures, VDBs, light images; a USDZ entry as its package)
// by path, size and modification time, FNV-1a as 16 hex digits: an edited or replaced asset is
// noticed without reading what can be gigabytes of volume data. A UDIM set's tiles are not listed.
std::string assetFilesStamp(const usd::Stage& stage) {
    std::set<std::string> files;
    for (const usd::AssetReference& a : stage.assetReferences()) {
        if (a.exists) files.insert(fileOnDisk(a.resolved));
    }
    std::uint64_t hash = kFnv1aOffsetBasis;
    for (const std::string& file : files) {
        std::error_code error;
        if (!std::filesystem::is_regular_file(file, error)) continue;
        const auto size = std::filesystem::file_size(file, error);
        const auto modified = std::filesystem::last_write_time(file, error).time_since_epoch().count();
        hash = fnv1a(file + '\0' + std::to_string(size) + '\0' + std::to_string(modified) + '\n', hash);
    }
    return hex(hash);
}

template <typename Items, typename Text>
std::string joined(const Items& items, Text text) {
    std::string out;
    for (const auto& item : items) {
        if (!out.empty()) out += ' ';
        out += text(item);
    }
    return out;
}

}  // namespace

CheckpointFingerprint renderFingerprint(const RenderOptions& o, const usd::Stage& stage, const ResolvedRender& r) {
    const auto size = [](int w, int h) { return std::to_string(w) + "x" + std::to_string(h); };
    return {
        {"fluence version", kFluenceVersion},
        {"scene", std::filesystem::absolute(o.scene).lexically_normal().string()},
        {"scene files", layerFilesHash(stage)},
        {"asset files", assetFilesStamp(stage)},
        {"camera", r.cameraPath},
        {"resolution", size(r.imageWidth, r.imageHeight)},
        {"window",
         size(r.windowWidth, r.windowHeight) + " at " + std::to_string(r.windowX) + "," + std::to_string(r.windowY)},
        {"frame", std::isnan(r.time) ? "default" : exact(r.time)},
        {"seed", std::to_string(o.seed)},
        {"integrator", r.integrator},
        {"sampler", r.sampler},
        {"integrator parameters",
         joined(r.integratorParameters, [](const auto& p) { return p.first + "=" + exact(p.second); })},
        {"samples per pixel", std::to_string(r.samplesPerPixel)},
        {"target error", exact(o.targetError)},
        {"mean spp", exact(o.meanSpp)},
        {"min spp", std::to_string(o.minSpp)},
        {"max depth", std::to_string(o.maxDepth)},
        {"light path layers",
         joined(r.lightPathLayers,
                [](const integrators::LightPathAov& l) { return l.name + "=" + l.expression.text(); })},
        {"variants",
         joined(o.variants,
                [](const usd::VariantSelection& v) { return v.primPath + ":" + v.variantSet + "=" + v.selection; })},
        {"set", joined(o.overrides, [](const AttributeOverride& a) { return a.text; })},
        {"purpose", o.purposes ? joined(*o.purposes, [](const std::string& p) { return p; }) : "(render settings)"},
        {"render settings", o.settings},
        {"subsurface", o.subsurface},
        {"dome sampling",
         o.domeSampling ? std::string(render::domeLightSamplingName(*o.domeSampling)) : "(render settings)"},
        {"default light", o.defaultLight ? "on" : "off"},
        {"motion blur", o.motionBlur ? "on" : "off"},
        {"dicing rate", exact(o.dicingRate)},
        {"subdiv level", o.subdivLevel ? std::to_string(*o.subdivLevel) : "(dicing)"},
        {"cryptomatte",
         joined(o.cryptomatte,
                [](CryptomatteSource s) { return s == CryptomatteSource::Object ? "object" : "material"; })},
    };
}

std::string fingerprintDigest(const CheckpointFingerprint& fingerprint) {
    std::uint64_t hash = kFnv1aOffsetBasis;
    for (const auto& [name, value] : fingerprint) {
        hash = fnv1a(name, hash);
        hash = fnv1a(std::string_view("\0", 1), hash);
        hash = fnv1a(value, hash);
        hash = fnv1a(std::string_view("\n", 1), hash);
    }
    return hex(hash);
}

}  // namespace fluence::app
