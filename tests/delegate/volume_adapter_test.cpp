// UsdVol Volumes read into render::VolumeDesc: fields, the volume material's inputs (constants,
// primvar readers, field readers), the fallback material, time-sampled file sequences, and
// missing files. On OpenUSD's own UsdVol test scenes (skipped when the corpus is absent).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "delegate/scene_delegate.h"
#include "tests/delegate/delegate_test_support.h"
#include "tests/support/shared_data.h"
#include "tests/support/temp_dir.h"

namespace fluence::delegate {
namespace {

namespace fs = std::filesystem;

const fs::path kVdbTests =
    test::sharedPath("usd_corpus/OpenUSD/pxr/usdImaging/usdImagingGL/testenv/testUsdImagingGLVdbVolume");

struct Opened {
    std::unique_ptr<usd::Stage> stage;
    DelegateResult result;
    std::vector<std::string> warnings;
};

Opened open(const fs::path& file, double time) {
    Opened o;
    o.stage = usd::Stage::open(file.string());
    DelegateOptions options;
    options.time = time;
    options.convertColor = [](const RGB& c, const std::string&) { return c; };
    options.warn = [&o](const std::string& path, const std::string& message) {
        o.warnings.push_back(path + ": " + message);
    };
    o.result = populateScene(*o.stage, options);
    return o;
}

TEST(VolumeAdapter, TwoFieldsAndAPreviewMaterialReadThroughPrimvarReaders) {
    FLUENCE_REQUIRE_SHARED(kVdbTests);
    Opened o = open(kVdbTests / "vdbVolumeTwoFields.usda", 1.0);
    ASSERT_EQ(o.result.scene.volumes.size(), 1u);
    const render::VolumeDesc& v = o.result.scene.volumes[0];
    EXPECT_EQ(v.name, "/Volume");
    ASSERT_TRUE(v.density);
    EXPECT_EQ(fs::path(v.density->file).filename(), "densityAndHeat.vdb");
    EXPECT_EQ(v.density->gridName, "density");
    ASSERT_TRUE(v.temperature) << "the preview shader's heat field";
    EXPECT_EQ(v.temperature->gridName, "heat");
    EXPECT_FALSE(v.color);
    EXPECT_FLOAT_EQ(v.params.densityScale, 3.0f) << "primvars:densityScale through a UsdPrimvarReader_float";
    EXPECT_EQ(v.params.albedo, RGB(0.8f));
    EXPECT_FLOAT_EQ(v.params.temperatureScale, 10.0f);
    // translate (0, -3, 0), then rotateX -90: the volume's +Z points along world +Y.
    Vec3d up = v.transform.transformVector(Vec3d(0, 0, 1));
    EXPECT_NEAR(up.y, 1.0, 1e-9);
    EXPECT_NEAR(v.transform.transformPoint(Vec3d(0, 0, 0)).y, -3.0, 1e-9);
}

TEST(VolumeAdapter, UnboundVolumesUseTheFallbackAndFileSequencesFollowTheFrame) {
    FLUENCE_REQUIRE_SHARED(kVdbTests);
    for (int frame : {1, 3}) {
        Opened o = open(kVdbTests / "vdbVolumeFallbackMaterial.usda", frame);
        ASSERT_EQ(o.result.scene.volumes.size(), 1u);
        const render::VolumeDesc& v = o.result.scene.volumes[0];
        EXPECT_EQ(fs::path(v.density->file).filename(), "smoke_00000" + std::to_string(frame) + ".vdb");
        EXPECT_FLOAT_EQ(v.params.densityScale, 1.0f);
        EXPECT_EQ(v.params.albedo, RGB(0.8f));
        EXPECT_FLOAT_EQ(v.params.blackbodyIntensity, 0.0f);
    }
}

TEST(VolumeAdapter, AFluenceVolumeShaderWithFieldReaders) {
    test::TempDir dir{"fluence_volume"};
    std::ofstream(dir.path() / "plume.vdb") << "read by volumes/, not here";
    auto p = testing::populate(R"(
def Volume "Plume" (
    prepend apiSchemas = ["MaterialBindingAPI"]
)
{
    rel field:density = </Plume/Density>
    rel field:temperature = </Plume/Temperature>
    rel material:binding = </Looks/Fire>
    def OpenVDBAsset "Density"
    {
        asset filePath = @)" + (dir.path() / "plume.vdb").string() +
                               R"(@
        token fieldName = "density"
    }
    def OpenVDBAsset "Temperature"
    {
        asset filePath = @)" + (dir.path() / "plume.vdb").string() +
                               R"(@
        token fieldName = "temperature"
        int fieldIndex = 1
    }
}
def Scope "Looks"
{
    def Material "Fire"
    {
        token outputs:volume.connect = </Looks/Fire/Shader.outputs:volume>
        def Shader "Shader"
        {
            uniform token info:id = "FluenceVolume"
            float inputs:density.connect = </Looks/Fire/Density.outputs:result>
            float inputs:temperature.connect = </Looks/Fire/Temperature.outputs:result>
            float inputs:densityScale = 4
            color3f inputs:albedo = (0.9, 0.7, 0.5)
            float inputs:anisotropy = 0.4
            float inputs:temperatureScale = 1000
            float inputs:temperatureOffset = 300
            float inputs:blackbodyIntensity = 2
            token outputs:volume
        }
        def Shader "Density"
        {
            uniform token info:id = "HwFieldReader_float"
            token inputs:fieldname = "density"
            float outputs:result
        }
        def Shader "Temperature"
        {
            uniform token info:id = "HwFieldReader_float"
            token inputs:fieldname = "temperature"
            float outputs:result
        }
    }
}
)");
    ASSERT_EQ(p.result.scene.volumes.size(), 1u);
    const render::VolumeDesc& v = p.result.scene.volumes[0];
    EXPECT_EQ(v.temperature->gridIndex, 1);
    EXPECT_FLOAT_EQ(v.params.densityScale, 4.0f);
    EXPECT_EQ(v.params.albedo, RGB(0.9f, 0.7f, 0.5f));
    EXPECT_FLOAT_EQ(v.params.anisotropy, 0.4f);
    EXPECT_FLOAT_EQ(v.params.temperatureScale, 1000.0f);
    EXPECT_FLOAT_EQ(v.params.temperatureOffset, 300.0f);
    EXPECT_FLOAT_EQ(v.params.blackbodyIntensity, 2.0f);
}

}  // namespace
}  // namespace fluence::delegate
