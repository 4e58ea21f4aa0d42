// UsdRender -> RenderSettingsDesc: the RenderSettings prim the render uses, its RenderProducts and
// their RenderVars, with the schema's fallbacks.
//
// Which settings prim: the one named on the command line (`-s/--settings`), else the root layer's
// `renderSettingsPrimPath`, else none (a stage without render settings renders with the CLI's
// defaults). Attributes read:
// | prim           | attribute (fallback)                                                        |
// |----------------|------------------------------------------------------------------------------|
// | RenderSettings | resolution (2048, 1080), pixelAspectRatio (1), aspectRatioConformPolicy      |
// |                | ("expandAperture"), rel camera, rel products, includedPurposes,              |
// |                | uniform token fluence:integrator ("": --integrator, else path),              |
// |                | bool fluence:defaultLight (true: a scene with no light gets the default ones)|
// |                | uniform token fluence:domeLightSampling ("": --dome-sampling, else auto;    |
// |                | render/dome_light_sampling.h, checked by the render command)                 |
// |                | fluence:<method>:<parameter> numbers (the integrators' parameters, e.g.     |
// |                | fluence:sppm:photons: the render command checks them, apps/integrator_parameters.h)|
// | RenderProduct  | productName (""), productType ("raster"), and the RenderSettingsBase         |
// |                | attributes above when authored on the product (they override the settings') |
// |                | — resolution, camera, pixelAspectRatio, aspectRatioConformPolicy,          |
// |                | dataWindowNDC ((0, 0, 1, 1)); driver:parameters:OpenEXR:compression ("")   |
// | RenderVar      | sourceName (""), sourceType ("raw"), dataType ("color3f"),                  |
// |                | driver:parameters:aov:name (the prim's name), fluence:filter ("")           |
// The delegate's own render uses the first product's resolution, camera and framing; the render
// command writes every product and var (apps/render_products.h). A policy outside USD's five
// tokens, a pixelAspectRatio that is not positive, or a dataWindowNDC that is not a float4 with
// min < max, raises SceneError naming the prim. `fluence:integrator` names the solution method
// (integrators/registry.cpp) when `fluence render` is not given `--integrator`; the delegate does
// not know the integrators, so the render command rejects a name that is none of them.
#pragma once

#include <array>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "render/camera.h"
#include "scene/stage.h"

namespace fluence::delegate {

struct RenderVarDesc {
    std::string path;  // prim path; its name is the AOV's name
    std::string sourceName, sourceType = "raw", dataType = "color3f";
    std::string aovName;  // driver:parameters:aov:name, else the prim's name: the EXR layer
    std::string filter;   // fluence:filter, "" when not authored
};

struct RenderProductDesc {
    std::string path;
    std::string productName;  // the output file
    std::string productType = "raster";
    std::pair<int, int> resolution;
    std::string cameraPath;
    render::ImageFraming framing;
    // The part of the image written, in NDC: (xmin, ymin, xmax, ymax), (0, 0) the bottom-left corner.
    std::array<float, 4> dataWindowNdc{0.0f, 0.0f, 1.0f, 1.0f};
    bool disableMotionBlur = false;  // UsdRenderSettingsBase disableMotionBlur, inherited from the settings
    std::string compression;         // driver:parameters:OpenEXR:compression, "" when not authored
    std::vector<RenderVarDesc> vars;
};

struct RenderSettingsDesc {
    std::string path;
    std::pair<int, int> resolution{2048, 1080};
    bool resolutionAuthored = false;
    std::string cameraPath;
    render::ImageFraming framing;
    std::vector<std::string> includedPurposes{"default", "render"};
    std::string integrator;         // fluence:integrator, "" when not authored
    std::string sampler;            // fluence:sampler, "" when not authored
    bool defaultLight = true;       // fluence:defaultLight (delegate/default_lights.h)
    std::string domeLightSampling;  // fluence:domeLightSampling, "" when not authored
    // UsdRenderSettingsBase disableMotionBlur (or its deprecated instantaneousShutter): every
    // camera's shutter is closed to an instant (husk reads it so too).
    bool disableMotionBlur = false;
    std::map<std::string, double> integratorParameters;  // authored fluence:<method>:<parameter>, by attribute name
    std::vector<RenderProductDesc> products;

    // The product this version renders: the first one (nullptr when there are none).
    const RenderProductDesc* renderedProduct() const { return products.empty() ? nullptr : &products.front(); }
    // The camera of the rendered product, which falls back to the settings' own camera.
    const std::string& renderedCamera() const { return renderedProduct() ? renderedProduct()->cameraPath : cameraPath; }
    // The framing of the rendered product, which falls back to the settings' own.
    const render::ImageFraming& renderedFraming() const {
        return renderedProduct() ? renderedProduct()->framing : framing;
    }
    // Whether the rendered product (else the settings) turns motion blur off.
    bool motionBlurDisabled() const {
        return renderedProduct() ? renderedProduct()->disableMotionBlur : disableMotionBlur;
    }
};

// `settingsPath` "" means the stage's renderSettingsPrimPath (or no settings). Throws SceneError
// when a named prim is not a RenderSettings prim, when a product or var relationship targets a
// prim of the wrong type, and when `settingsPath` names no prim. When the stage's
// renderSettingsPrimPath names no prim (a layer written for another stage, as arnold-usd's tests
// have), `warnMissing` is told (where, message) and there are no settings, as husk does; without
// `warnMissing` (--strict) that is a SceneError too.
std::optional<RenderSettingsDesc> renderSettingsFromStage(
    const usd::Stage& stage, const std::string& settingsPath, double time,
    const std::function<void(const std::string& where, const std::string& message)>& warnMissing);

}  // namespace fluence::delegate
