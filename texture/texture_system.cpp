#include "texture/texture_system.h"

#include <OpenImageIO/imagecache.h>
#include <OpenImageIO/texture.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <tuple>
#include <vector>

#include "scene/package_files.h"

namespace fluence::texture {

namespace OIIO = OIIO_NAMESPACE;

struct TextureSystem::Texture {
    OIIO::TextureSystem::TextureHandle* handle = nullptr;
    bool udim = false;
    int channels = 0;
    color::ColorConversion toRendering;
};

struct TextureSystem::Impl {
    explicit Impl(color::ColorManagement c) : colors(std::move(c)) {}
    color::ColorManagement colors;
    OIIO::ImageCache* cache = nullptr;  // the system's own, created and destroyed here: OpenImageIO 2.4
                                        // leaks the one create(false) makes itself (LeakSanitizer)
    OIIO::TextureSystem* system = nullptr;
    std::mutex mutex;  // guards `opened`
    std::map<std::tuple<std::string, SourceColorSpace, std::string>, Texture> opened;
};

TextureSystem::TextureSystem(color::ColorManagement colors) : impl_(std::make_unique<Impl>(std::move(colors))) {
    impl_->cache = OIIO::ImageCache::create(false);
    impl_->system = OIIO::TextureSystem::create(false, impl_->cache);
    impl_->system->attribute("automip", 1);
    impl_->system->attribute("max_memory_MB", 2048.0f);
}

TextureSystem::~TextureSystem() {
    OIIO::TextureSystem::destroy(impl_->system);
    OIIO::ImageCache::destroy(impl_->cache);
}

namespace {

// The colour space the values of a file with `spec` are in, by UsdUVTexture's rules.
std::string sourceSpace(const OIIO::ImageSpec& spec, SourceColorSpace colorSpace,
                        const color::ColorManagement& colors) {
    if (colorSpace == SourceColorSpace::Raw) return "raw";
    if (colorSpace == SourceColorSpace::SRGB) return "sRGB";
    std::string stated = spec.get_string_attribute("oiio:ColorSpace");
    if (!stated.empty() && colors.hasColorSpace(stated)) return stated;
    return spec.format.is_floating_point() ? "" : "sRGB";
}

// Bilinear by default: exact at texel centres, no blur within a level.
OIIO::TextureOpt::InterpMode oiioInterpolation(Filter filter) {
    switch (filter) {
        case Filter::Closest: return OIIO::TextureOpt::InterpClosest;
        case Filter::Linear: return OIIO::TextureOpt::InterpBilinear;
        case Filter::Cubic: return OIIO::TextureOpt::InterpBicubic;
    }
    return OIIO::TextureOpt::InterpBilinear;
}

OIIO::TextureOpt::Wrap oiioWrap(Wrap wrap) {
    switch (wrap) {
        case Wrap::Black: return OIIO::TextureOpt::WrapBlack;
        case Wrap::Clamp: return OIIO::TextureOpt::WrapClamp;
        case Wrap::Repeat: return OIIO::TextureOpt::WrapPeriodic;
        case Wrap::Mirror: return OIIO::TextureOpt::WrapMirror;
    }
    return OIIO::TextureOpt::WrapBlack;
}

}  // namespace

const TextureSystem::Texture* TextureSystem::open(const std::string& path, SourceColorSpace colorSpace,
                                                  std::string& error, const std::string& namedSpace) {
    std::lock_guard<std::mutex> lock(impl_->mutex);
    auto key = std::make_tuple(path, colorSpace, namedSpace);
    if (auto it = impl_->opened.find(key); it != impl_->opened.end()) return &it->second;

    OIIO::TextureSystem& ts = *impl_->system;
    OIIO::ustring name(usd::fileForAsset(path));  // a texture inside a USDZ package: its extracted copy
    Texture texture;
    texture.handle = ts.get_texture_handle(name);
    texture.udim = texture.handle && ts.is_udim(texture.handle);
    // The file whose header says what the texture holds: itself, or a UDIM set's first tile.
    OIIO::ustring first = name;
    if (texture.udim) {
        std::vector<OIIO::ustring> tiles;
        int nu = 0, nv = 0;
        ts.inventory_udim(name, tiles, nu, nv);
        auto found = std::find_if(tiles.begin(), tiles.end(), [](const OIIO::ustring& t) { return !t.empty(); });
        if (found == tiles.end()) {
            error = "no tile of the UDIM set " + path + " exists";
            return nullptr;
        }
        first = *found;
    }
    const OIIO::ImageSpec* spec = ts.imagespec(first);
    if (!texture.handle || !spec) {
        std::string reason = ts.geterror();
        reason = reason.substr(0, reason.find('\n'));  // OpenImageIO repeats the cause on further lines
        error = "cannot read texture " + path + (reason.empty() ? "" : ": " + reason);
        return nullptr;
    }
    texture.channels = spec->nchannels;
    std::string space = namedSpace.empty() ? sourceSpace(*spec, colorSpace, impl_->colors) : namedSpace;
    try {
        texture.toRendering = impl_->colors.conversionToRenderingSpace(space);
    } catch (const color::ColorError& e) {
        error = "texture " + path + ": " + e.what();
        return nullptr;
    }
    return &impl_->opened.emplace(key, std::move(texture)).first->second;
}

bool TextureSystem::lookup(const Texture& texture, float s, float t, const Footprint& f, Wrap wrapS, Wrap wrapT,
                           std::array<float, 4>& rgba, Filter filter) const {
    OIIO::TextureOpt options;
    options.swrap = oiioWrap(wrapS);
    options.twrap = oiioWrap(wrapT);
    options.interpmode = oiioInterpolation(filter);
    // OIIO's t runs down the image; USD's up. Within a UDIM tile the flip is per tile.
    float oiioT;
    if (texture.udim) {
        float tile = std::floor(t);
        oiioT = tile + std::min(1.0f - (t - tile), 0.99999994f);
    } else {
        oiioT = 1.0f - t;
    }
    float result[4] = {0.0f, 0.0f, 0.0f, 1.0f};
    const int channels = std::min(texture.channels, 4);
    OIIO::TextureSystem::Perthread* thread = impl_->system->get_perthread_info();
    bool ok = impl_->system->texture(texture.handle, thread, options, s, oiioT, f.dsdx, -f.dtdx, f.dsdy, -f.dtdy,
                                     channels, result);
    if (!ok) return false;
    if (channels <= 2) {  // grey, or grey and alpha
        float alpha = channels == 2 ? result[1] : 1.0f;
        result[1] = result[2] = result[0];
        result[3] = alpha;
    } else if (channels == 3) {
        result[3] = 1.0f;
    }
    RGB c = texture.toRendering.apply(RGB(result[0], result[1], result[2]));
    rgba = {c.x, c.y, c.z, result[3]};
    return true;
}

}  // namespace fluence::texture
