#include "color/display_pipeline.h"

#include <algorithm>
#include <cmath>
#include <mutex>

#include "color/color_management.h"
#include "color/ocio_config.h"

namespace OCIO = OCIO_NAMESPACE;

namespace fluence::color {

struct DisplayPipeline::Impl {
    OCIO::ConstConfigRcPtr config;
    std::string description;
    // OCIO 2.1's Config fills display caches lazily without a lock (color_management.cpp).
    mutable std::mutex mutex;
};

namespace {

// Distinct values the dynamic properties are set to, to tell which uniform each one drives.
constexpr double kExposureProbe = 1234.5;
constexpr double kGammaProbe = 6789.5;

// Expects the config's mutex held.
OCIO::ConstProcessorRcPtr buildProcessor(const OCIO::ConstConfigRcPtr& config, const std::string& inputSpace,
                                         const DisplaySettings& s) {
    const std::string display = s.display.empty() ? config->getDefaultDisplay() : s.display;
    bool knownDisplay = false;
    for (int i = 0; i < config->getNumDisplays(); ++i) knownDisplay |= display == config->getDisplay(i);
    if (!knownDisplay) throw ColorError("unknown OCIO display '" + display + "'");
    const std::string view = s.view.empty() ? config->getDefaultView(display.c_str()) : s.view;
    bool knownView = false;
    for (int i = 0; i < config->getNumViews(display.c_str()); ++i)
        knownView |= view == config->getView(display.c_str(), i);
    if (!knownView) throw ColorError("unknown OCIO view '" + view + "' of display '" + display + "'");
    if (!s.look.empty() && !config->getLook(s.look.c_str())) throw ColorError("unknown OCIO look '" + s.look + "'");
    if (!config->getColorSpace(inputSpace.c_str())) throw ColorError("unknown OCIO colour space '" + inputSpace + "'");

    auto displayView = OCIO::DisplayViewTransform::Create();
    displayView->setSrc(inputSpace.c_str());
    displayView->setDisplay(display.c_str());
    displayView->setView(view.c_str());

    auto exposure = OCIO::ExposureContrastTransform::Create();
    exposure->setStyle(OCIO::EXPOSURE_CONTRAST_LINEAR);
    exposure->setPivot(0.18);
    exposure->makeExposureDynamic();
    auto gamma = OCIO::ExposureContrastTransform::Create();
    gamma->setStyle(OCIO::EXPOSURE_CONTRAST_VIDEO);
    gamma->setPivot(1.0);
    gamma->makeGammaDynamic();

    auto pipeline = OCIO::LegacyViewingPipeline::Create();
    pipeline->setDisplayViewTransform(displayView);
    pipeline->setLinearCC(exposure);
    pipeline->setDisplayCC(gamma);
    if (!s.look.empty()) {
        pipeline->setLooksOverrideEnabled(true);
        pipeline->setLooksOverride(s.look.c_str());
    }
    return pipeline->getProcessor(config, config->getCurrentContext());
}

// The shader of `gpu`, textures at most `maxWidth` wide (0: OCIO's default).
OCIO::GpuShaderDescRcPtr extractShader(const OCIO::ConstGPUProcessorRcPtr& gpu, unsigned maxWidth) {
    auto desc = OCIO::GpuShaderDesc::CreateShaderDesc();
    desc->setLanguage(OCIO::GPU_LANGUAGE_GLSL_ES_3_0);
    desc->setFunctionName("ocioDisplay");
    desc->setResourcePrefix("ocio");
    if (maxWidth) desc->setTextureMaxWidth(maxWidth);
    gpu->extractGpuShaderInfo(desc);
    return desc;
}

void setDynamic(OCIO::DynamicPropertyRcPtr property, double value) {
    OCIO::DynamicPropertyValue::AsDouble(property)->setValue(value);
}

// One of a GPU shader's 1D/2D LUT textures, as OCIO describes it.
struct TextureInfo {
    const char* name = nullptr;
    const char* sampler = nullptr;
    unsigned width = 0, height = 0;
    OCIO::GpuShaderDesc::TextureType channel{};
    OCIO::Interpolation interpolation{};
};

TextureInfo textureInfo(const OCIO::GpuShaderDescRcPtr& desc, unsigned i) {
    TextureInfo t;
    desc->getTexture(i, t.name, t.sampler, t.width, t.height, t.channel, t.interpolation);
    return t;
}

// `use` applied to the processor of these settings, built under the config's lock; OCIO's
// exceptions become ColorErrors.
template <class Use>
auto withProcessor(std::mutex& mutex, const OCIO::ConstConfigRcPtr& config, const std::string& inputSpace,
                   const DisplaySettings& settings, Use&& use) {
    try {
        std::lock_guard lock(mutex);
        return use(buildProcessor(config, inputSpace, settings));
    } catch (const OCIO::Exception& e) {
        throw ColorError(std::string("OCIO: ") + e.what());
    }
}

}  // namespace

DisplayPipeline DisplayPipeline::open(const std::string& configPath) {
    auto impl = std::make_shared<Impl>();
    detail::LoadedConfig loaded = detail::loadOcioConfig(configPath);
    impl->config = std::move(loaded.config);
    impl->description = std::move(loaded.description);
    if (impl->config->getNumDisplays() == 0)
        throw ColorError("OCIO config " + impl->description + " defines no display");
    return DisplayPipeline(std::move(impl));
}

std::string DisplayPipeline::configDescription() const { return impl_->description; }

DisplayMenus DisplayPipeline::menus() const {
    std::lock_guard lock(impl_->mutex);
    const OCIO::ConstConfigRcPtr& config = impl_->config;
    DisplayMenus menus;
    menus.defaultDisplay = config->getDefaultDisplay();
    for (int i = 0; i < config->getNumDisplays(); ++i) {
        const std::string display = config->getDisplay(i);
        menus.displays.push_back(display);
        menus.defaultViews[display] = config->getDefaultView(display.c_str());
        for (int v = 0; v < config->getNumViews(display.c_str()); ++v)
            menus.views[display].push_back(config->getView(display.c_str(), v));
    }
    for (int i = 0; i < config->getNumLooks(); ++i) menus.looks.push_back(config->getLookNameByIndex(i));
    return menus;
}

std::string DisplayPipeline::inputSpace(const std::string& space) const {
    std::lock_guard lock(impl_->mutex);
    if (!space.empty())
        if (const char* name = impl_->config->getCanonicalName(space.c_str()); name && *name) return name;
    const char* sceneLinear = impl_->config->getCanonicalName(OCIO::ROLE_SCENE_LINEAR);
    if (sceneLinear == nullptr || *sceneLinear == '\0')
        throw ColorError("OCIO config " + impl_->description + " has no colour space '" + space +
                         "' and no scene_linear role");
    return sceneLinear;
}

GpuDisplayShader DisplayPipeline::gpuShader(const std::string& inputSpace, const DisplaySettings& settings) const {
    const OCIO::ConstGPUProcessorRcPtr gpu =
        withProcessor(impl_->mutex, impl_->config, inputSpace, settings,
                      [](const OCIO::ConstProcessorRcPtr& p) { return p->getDefaultGPUProcessor(); });
    // OCIO 2.1's GLSL ES code packs a 1D LUT of N entries into an N x 1 texture but looks the last
    // entry (an input >= 1) up in row 1, which does not exist, and so reads entry 0: narrower rows
    // (the texture then two rows high) put the last entry where the lookup goes. Each pass narrows
    // the widest one-row texture, so the loop ends.
    OCIO::GpuShaderDescRcPtr desc;
    for (unsigned maxWidth = 0;;) {
        desc = extractShader(gpu, maxWidth);
        unsigned narrower = 0;
        for (unsigned i = 0; i < desc->getNumTextures(); ++i) {
            const TextureInfo t = textureInfo(desc, i);
            if (t.height == 1 && t.width > 2) narrower = narrower ? std::min(narrower, t.width - 1) : t.width - 1;
        }
        if (narrower == 0) break;
        maxWidth = narrower;
    }

    GpuDisplayShader shader;
    shader.functionName = "ocioDisplay";
    shader.text = desc->getShaderText();
    for (unsigned i = 0; i < desc->getNumTextures(); ++i) {
        const TextureInfo t = textureInfo(desc, i);
        const float* values = nullptr;
        desc->getTextureValues(i, values);
        GpuLutTexture lut{t.name,
                          t.sampler,
                          int(t.width),
                          int(t.height),
                          0,
                          t.channel == OCIO::GpuShaderDesc::TEXTURE_RED_CHANNEL ? 1 : 3,
                          t.interpolation != OCIO::INTERP_NEAREST,
                          {}};
        lut.values.assign(values, values + std::size_t(t.width) * t.height * lut.channels);
        shader.textures.push_back(std::move(lut));
    }
    for (unsigned i = 0; i < desc->getNum3DTextures(); ++i) {
        const char *texture = nullptr, *sampler = nullptr;
        unsigned edge = 0;
        OCIO::Interpolation interpolation{};
        desc->get3DTexture(i, texture, sampler, edge, interpolation);
        const float* values = nullptr;
        desc->get3DTextureValues(i, values);
        GpuLutTexture lut{texture, sampler, int(edge), int(edge), int(edge), 3, interpolation != OCIO::INTERP_NEAREST,
                          {}};
        lut.values.assign(values, values + std::size_t(edge) * edge * edge * 3);
        shader.textures.push_back(std::move(lut));
    }
    // Which uniform each dynamic property drives: set each to a probe value and read them back.
    setDynamic(desc->getDynamicProperty(OCIO::DYNAMIC_PROPERTY_EXPOSURE), kExposureProbe);
    setDynamic(desc->getDynamicProperty(OCIO::DYNAMIC_PROPERTY_GAMMA), kGammaProbe);
    for (unsigned i = 0; i < desc->getNumUniforms(); ++i) {
        OCIO::GpuShaderDesc::UniformData data;
        const std::string name = desc->getUniform(i, data);
        if (data.m_type != OCIO::UNIFORM_DOUBLE || !data.m_getDouble)
            throw ColorError("OCIO shader uniform '" + name + "' is not a number the review page can set");
        const double value = data.m_getDouble();
        if (value == kExposureProbe)
            shader.uniforms.push_back({name, "exposure"});
        else if (value == kGammaProbe)
            shader.uniforms.push_back({name, "gamma"});
        else
            throw ColorError("OCIO shader uniform '" + name + "' is driven by no setting of the review page");
    }
    return shader;
}

void DisplayPipeline::applyCpu(const std::string& inputSpace, const DisplaySettings& settings, float* rgba,
                               std::size_t count) const {
    const OCIO::ConstCPUProcessorRcPtr cpu =
        withProcessor(impl_->mutex, impl_->config, inputSpace, settings,
                      [](const OCIO::ConstProcessorRcPtr& p) { return p->getDefaultCPUProcessor(); });
    setDynamic(cpu->getDynamicProperty(OCIO::DYNAMIC_PROPERTY_EXPOSURE), settings.exposureStops);
    setDynamic(cpu->getDynamicProperty(OCIO::DYNAMIC_PROPERTY_GAMMA), 1.0 / settings.gamma);
    OCIO::PackedImageDesc image(rgba, static_cast<long>(count), 1, 4);
    cpu->apply(image);
}

}  // namespace fluence::color
