#include "color/color_management.h"

#include "color/ocio_config.h"

#include <OpenColorIO/OpenColorIO.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <utility>

namespace OCIO = OCIO_NAMESPACE;

namespace fluence::color {

namespace {

// OCIO converts packed RGB through an RGBA scratch line as wide as the image: apply in chunks so
// the scratch memory stays small however many triples are passed.
constexpr std::size_t kChunk = 4096;

void applyProcessor(const OCIO::ConstCPUProcessorRcPtr& processor, float* rgb, std::size_t count) {
    for (std::size_t start = 0; start < count; start += kChunk) {
        const std::size_t n = std::min(kChunk, count - start);
        OCIO::PackedImageDesc desc(rgb + 3 * start, static_cast<long>(n), 1, 3);
        processor->apply(desc);
    }
}

}  // namespace

struct ColorManagement::Impl {
    OCIO::ConstConfigRcPtr config;
    std::string description;
    std::string renderingName;  // canonical name of kRenderingSpace in this config

    // Guards every use of `config` and the cache. OCIO 2.1's Config is not safe for concurrent
    // queries: getDefaultDisplay()/getDefaultView()/getDisplay() lazily fill an internal display
    // cache without a lock (ThreadSanitizer reports the race). CPU processors, once built, are
    // thread-safe, so processors are applied outside the lock.
    mutable std::mutex mutex;
    // Processors by key: "<canonical source>" for conversions to the rendering space,
    // "\x01<display>\x01<view>" for display/view transforms. A null processor means "no-op".
    mutable std::map<std::string, OCIO::ConstCPUProcessorRcPtr> cache;

    // The members below expect `mutex` to be held.

    std::string canonical(const std::string& space) const {
        if (space.empty()) return renderingName;
        const char* name = config->getCanonicalName(space.c_str());
        return name ? std::string(name) : std::string();
    }

    OCIO::ConstCPUProcessorRcPtr toRendering(const std::string& fromSpace) const {
        const std::string src = canonical(fromSpace);
        if (src.empty()) throw ColorError("unknown colour space '" + fromSpace + "' (not in " + description + ")");
        if (src == renderingName) return nullptr;
        auto it = cache.find(src);
        if (it != cache.end()) return it->second;
        OCIO::ConstCPUProcessorRcPtr cpu;
        try {
            auto processor = config->getProcessor(src.c_str(), renderingName.c_str());
            if (!processor->isNoOp()) cpu = processor->getDefaultCPUProcessor();
        } catch (const OCIO::Exception& e) {
            throw ColorError("cannot convert colour space '" + fromSpace + "' to " + renderingName + ": " + e.what());
        }
        cache.emplace(src, cpu);
        return cpu;
    }

    std::string resolveDisplay(const std::string& display) const {
        if (display.empty()) return config->getDefaultDisplay();
        for (int i = 0; i < config->getNumDisplaysAll(); ++i)
            if (display == config->getDisplayAll(i)) return display;
        throw ColorError("unknown display '" + display + "' (not in " + description + ")");
    }

    std::string resolveView(const std::string& display, const std::string& view) const {
        if (view.empty()) return config->getDefaultView(display.c_str());
        for (int i = 0; i < config->getNumViews(OCIO::VIEW_DISPLAY_DEFINED, display.c_str()); ++i)
            if (view == config->getView(OCIO::VIEW_DISPLAY_DEFINED, display.c_str(), i)) return view;
        for (int i = 0; i < config->getNumViews(OCIO::VIEW_SHARED, display.c_str()); ++i)
            if (view == config->getView(OCIO::VIEW_SHARED, display.c_str(), i)) return view;
        throw ColorError("unknown view '" + view + "' of display '" + display + "' (not in " + description + ")");
    }

    OCIO::ConstCPUProcessorRcPtr displayView(const std::string& displayIn, const std::string& viewIn) const {
        const std::string display = resolveDisplay(displayIn);
        const std::string view = resolveView(display, viewIn);
        const std::string key = "\x01" + display + "\x01" + view;
        auto it = cache.find(key);
        if (it != cache.end()) return it->second;
        OCIO::ConstCPUProcessorRcPtr cpu;
        try {
            auto transform = OCIO::DisplayViewTransform::Create();
            transform->setSrc(renderingName.c_str());
            transform->setDisplay(display.c_str());
            transform->setView(view.c_str());
            auto processor = config->getProcessor(transform);
            if (!processor->isNoOp()) cpu = processor->getDefaultCPUProcessor();
        } catch (const OCIO::Exception& e) {
            throw ColorError("cannot build display transform '" + display + "' / '" + view + "': " + e.what());
        }
        cache.emplace(key, cpu);
        return cpu;
    }
};

ColorManagement::ColorManagement(std::shared_ptr<const Impl> impl) : impl_(std::move(impl)) {}

ColorManagement ColorManagement::load(const std::string& configPath) {
    auto impl = std::make_shared<Impl>();
    detail::LoadedConfig loaded = detail::loadOcioConfig(configPath);
    impl->config = std::move(loaded.config);
    impl->description = std::move(loaded.description);

    const char* rendering = impl->config->getCanonicalName(kRenderingSpace);
    if (rendering == nullptr || *rendering == '\0')
        throw ColorError("OCIO config " + impl->description + " has no colour space (or alias) named '" +
                         kRenderingSpace + "', the Fluence rendering space (linear Rec.709)");
    impl->renderingName = rendering;
    if (impl->config->getNumDisplaysAll() == 0)
        throw ColorError("OCIO config " + impl->description + " defines no display");
    return ColorManagement(std::move(impl));
}

std::string ColorManagement::configDescription() const { return impl_->description; }

bool ColorManagement::hasColorSpace(const std::string& space) const {
    std::lock_guard<std::mutex> lock(impl_->mutex);
    return !impl_->canonical(space).empty();
}

void ColorManagement::toRenderingSpace(const std::string& fromSpace, float* rgb, std::size_t count) const {
    OCIO::ConstCPUProcessorRcPtr processor;
    {
        std::lock_guard<std::mutex> lock(impl_->mutex);
        processor = impl_->toRendering(fromSpace);
    }
    if (processor && count > 0) applyProcessor(processor, rgb, count);
}

RGB ColorManagement::toRenderingSpace(const std::string& fromSpace, RGB c) const {
    float v[3] = {c.x, c.y, c.z};
    toRenderingSpace(fromSpace, v, 1);
    return {v[0], v[1], v[2]};
}

struct ColorConversion::Processor {
    OCIO::ConstCPUProcessorRcPtr cpu;
};

RGB ColorConversion::apply(RGB c) const {
    if (!processor_) return c;
    float v[3] = {c.x, c.y, c.z};
    processor_->cpu->applyRGB(v);
    return {v[0], v[1], v[2]};
}

ColorConversion ColorManagement::conversionToRenderingSpace(const std::string& fromSpace) const {
    OCIO::ConstCPUProcessorRcPtr processor;
    {
        std::lock_guard<std::mutex> lock(impl_->mutex);
        processor = impl_->toRendering(fromSpace);
    }
    if (!processor) return ColorConversion();
    return ColorConversion(std::make_shared<const ColorConversion::Processor>(ColorConversion::Processor{processor}));
}

void ColorManagement::applyDisplayView(const std::string& display, const std::string& view, float* rgb,
                                       std::size_t count) const {
    OCIO::ConstCPUProcessorRcPtr processor;
    {
        std::lock_guard<std::mutex> lock(impl_->mutex);
        processor = impl_->displayView(display, view);
    }
    if (count == 0) return;
    if (processor) applyProcessor(processor, rgb, count);
    for (std::size_t i = 0; i < 3 * count; ++i) {
        const float v = rgb[i];
        rgb[i] = std::isnan(v) ? 0.0f : std::clamp(v, 0.0f, 1.0f);
    }
}

std::string ColorManagement::defaultDisplay() const {
    std::lock_guard<std::mutex> lock(impl_->mutex);
    return impl_->config->getDefaultDisplay();
}

std::string ColorManagement::defaultView(const std::string& display) const {
    std::lock_guard<std::mutex> lock(impl_->mutex);
    const std::string resolved = impl_->resolveDisplay(display);
    return impl_->config->getDefaultView(resolved.c_str());
}

std::array<float, 8> ColorManagement::renderingChromaticities() {
    return {0.64f, 0.33f, 0.30f, 0.60f, 0.15f, 0.06f, 0.3127f, 0.3290f};
}

}  // namespace fluence::color
