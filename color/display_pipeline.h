// The viewer's display pipeline: scene-linear pixels through an exposure (stops, before the view),
// the config's display/view transform with an optional look, and a display gamma (after it), as
// OCIO's LegacyViewingPipeline builds it for ociodisplay: exposure is an ExposureContrastTransform
// (linear style, pivot 0.18) and gamma one in video style (pivot 1, gamma 1/g), both dynamic
// properties, so a GPU shader built once takes them as uniforms. The same pipeline runs on the CPU
// (the reference the review page's pixels are tested against) and yields the GLSL ES 3.0 shader
// and LUT textures OCIO generates for WebGL2. OCIO headers stay out of this header.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace fluence::color {

struct DisplaySettings {
    std::string display;  // "" means the config's default display
    std::string view;     // "" means the display's default view
    std::string look;     // "" means the view's own looks (none overridden)
    double exposureStops = 0.0;
    double gamma = 1.0;
};

// What a config offers a viewer's menus.
struct DisplayMenus {
    std::vector<std::string> displays;
    std::map<std::string, std::vector<std::string>> views;  // by display
    std::vector<std::string> looks;
    std::string defaultDisplay;
    std::map<std::string, std::string> defaultViews;  // by display
};

// A LUT texture of the generated shader, values as OCIO gives them (RGB or red only).
struct GpuLutTexture {
    std::string textureName;
    std::string samplerName;
    int width = 0, height = 0, depth = 0;  // depth 0: a 1D/2D texture; a 3D LUT has width=height=depth
    int channels = 3;                      // 3 (RGB) or 1 (red)
    bool linearInterpolation = true;       // else nearest
    std::vector<float> values;
};

// A uniform of the generated shader driven by one of the pipeline's settings.
struct GpuUniform {
    std::string name;
    std::string setting;  // "exposure" (the value is the exposure in stops) or "gamma" (the value 1/gamma)
};

struct GpuDisplayShader {
    std::string functionName;  // vec4 functionName(vec4 linearRgba)
    std::string text;          // GLSL ES 3.0: uniforms, samplers and the function
    std::vector<GpuLutTexture> textures;
    std::vector<GpuUniform> uniforms;
};

class DisplayPipeline {
public:
    // Loads the config as ColorManagement::load does (path, else $OCIO, else built in). Throws ColorError.
    static DisplayPipeline open(const std::string& configPath = {});

    std::string configDescription() const;
    DisplayMenus menus() const;
    // The space pixels are in: `space` if the config knows it, else its scene_linear role.
    std::string inputSpace(const std::string& space) const;

    // The shader for (display, view, look) from `inputSpace`; exposure and gamma are uniforms.
    // Throws ColorError for an unknown display, view, look or space.
    GpuDisplayShader gpuShader(const std::string& inputSpace, const DisplaySettings& settings) const;
    // The same transform on the CPU over `count` RGBA pixels in place (not clamped).
    void applyCpu(const std::string& inputSpace, const DisplaySettings& settings, float* rgba, std::size_t count) const;

private:
    struct Impl;
    explicit DisplayPipeline(std::shared_ptr<const Impl> impl) : impl_(std::move(impl)) {}
    std::shared_ptr<const Impl> impl_;
};

}  // namespace fluence::color
