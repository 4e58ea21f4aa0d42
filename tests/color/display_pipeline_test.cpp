// color/display_pipeline.h: the review page's OCIO pipeline on the CPU and as a GLSL ES 3.0 shader.
#include "color/display_pipeline.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "color/color_management.h"

namespace fluence::color {
namespace {

std::vector<float> sampleRgba() {
    return {0.0f, 0.0f, 0.0f, 1.0f, 0.02f, 0.18f, 0.5f, 1.0f, 0.9f, 0.4f, 0.05f, 1.0f, 2.0f, 1.0f, 0.25f, 1.0f};
}

TEST(DisplayPipeline, AtExposureZeroAndGammaOneItIsTheDisplayViewTransform) {
    const DisplayPipeline pipeline = DisplayPipeline::open();
    const ColorManagement colors = ColorManagement::load();
    std::vector<float> rgba = sampleRgba();
    std::vector<float> rgb;
    for (std::size_t i = 0; i < rgba.size(); i += 4) rgb.insert(rgb.end(), rgba.begin() + i, rgba.begin() + i + 3);
    pipeline.applyCpu(pipeline.inputSpace("lin_rec709"), {"sRGB", "Standard", "", 0.0, 1.0}, rgba.data(), 4);
    colors.applyDisplayView("sRGB", "Standard", rgb.data(), 4);
    for (std::size_t p = 0; p < 4; ++p)
        for (std::size_t c = 0; c < 3; ++c)
            EXPECT_NEAR(std::min(1.0f, std::max(0.0f, rgba[p * 4 + c])), rgb[p * 3 + c], 1e-6f) << p << " " << c;
}

TEST(DisplayPipeline, ExposureScalesSceneLinearByTwoToTheStopsAndGammaIsOneOverG) {
    const DisplayPipeline pipeline = DisplayPipeline::open();
    const std::string space = pipeline.inputSpace("lin_rec709");
    std::vector<float> raw = sampleRgba(), exposed = sampleRgba();
    pipeline.applyCpu(space, {"sRGB", "Raw", "", 0.0, 1.0}, raw.data(), 4);
    pipeline.applyCpu(space, {"sRGB", "Raw", "", 1.0, 1.0}, exposed.data(), 4);
    for (std::size_t i = 0; i < raw.size(); ++i)
        if (i % 4 != 3) {
            EXPECT_NEAR(exposed[i], 2.0f * raw[i], 1e-6f) << i;
        }
    std::vector<float> gamma = sampleRgba();
    pipeline.applyCpu(space, {"sRGB", "Raw", "", 0.0, 2.0}, gamma.data(), 4);
    EXPECT_NEAR(gamma[5], std::pow(0.18f, 0.5f), 1e-5f);
}

TEST(DisplayPipeline, TheShaderIsGlslEs3WithExposureAndGammaAsUniforms) {
    const DisplayPipeline pipeline = DisplayPipeline::open();
    const GpuDisplayShader shader = pipeline.gpuShader(pipeline.inputSpace(""), {"", "", "", 0.0, 1.0});
    EXPECT_EQ(shader.functionName, "ocioDisplay");
    EXPECT_NE(shader.text.find("vec4 ocioDisplay(vec4 inPixel)"), std::string::npos);
    ASSERT_EQ(shader.uniforms.size(), 2u);
    EXPECT_EQ(shader.uniforms[0].setting, "exposure");
    EXPECT_EQ(shader.uniforms[1].setting, "gamma");
    for (const GpuUniform& u : shader.uniforms)
        EXPECT_NE(shader.text.find("uniform float " + u.name + ";"), std::string::npos) << u.name;
}

TEST(DisplayPipeline, MenusComeFromTheConfigAndUnknownNamesAreErrors) {
    const DisplayPipeline pipeline = DisplayPipeline::open();
    const DisplayMenus menus = pipeline.menus();
    EXPECT_EQ(menus.defaultDisplay, "sRGB");
    EXPECT_EQ(menus.views.at("sRGB"), (std::vector<std::string>{"Standard", "Raw"}));
    EXPECT_EQ(menus.defaultViews.at("sRGB"), "Standard");
    const std::string space = pipeline.inputSpace("");
    EXPECT_THROW(pipeline.gpuShader(space, {"sRGB", "Nope", "", 0.0, 1.0}), ColorError);
    EXPECT_THROW(pipeline.gpuShader(space, {"Nope", "", "", 0.0, 1.0}), ColorError);
    EXPECT_THROW(pipeline.gpuShader(space, {"", "", "NoLook", 0.0, 1.0}), ColorError);
    EXPECT_EQ(pipeline.inputSpace("no such space"), pipeline.inputSpace("lin_rec709"));
}

}  // namespace
}  // namespace fluence::color
