// UsdVol volumes enter the render index with their fields (rendering them is the volume issue).
#include <gtest/gtest.h>

#include "delegate/scene_delegate.h"
#include "scene/usda_parser.h"

namespace fluence::delegate {
namespace {

TEST(VolumeIndex, FieldsAreReadFromOpenVDBAssets) {
    auto stage = std::make_unique<usd::Stage>(usd::parseUsdaString(R"(#usda 1.0
def Camera "Cam"
{
}
def Volume "Smoke"
{
    rel field:density = </Smoke/Density>
    rel field:temperature = </Smoke/Missing>
    def OpenVDBAsset "Density"
    {
        asset filePath = @/data/smoke.vdb@
        token fieldName = "density"
        int fieldIndex = 0
    }
}
)",
                                                                   "volume.usda"));
    std::vector<std::string> warnings;
    DelegateOptions options;
    options.convertColor = [](const RGB& c, const std::string&) { return c; };
    options.warn = [&](const std::string& path, const std::string& message) { warnings.push_back(path + ": " + message); };
    SceneDelegate delegate(*stage, options);
    delegate.sync();
    const auto* volume = dynamic_cast<const VolumeRprim*>(delegate.renderIndex().find("/Smoke"));
    ASSERT_NE(volume, nullptr);
    ASSERT_EQ(volume->fields().size(), 1u);
    const auto& field = volume->fields()[0];
    EXPECT_EQ(field.name, "density");
    EXPECT_EQ(field.assetPrim, "/Smoke/Density");
    EXPECT_EQ(field.filePath, "/data/smoke.vdb");
    EXPECT_EQ(field.gridName, "density");
    EXPECT_EQ(field.fieldIndex, 0);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("field 'temperature' targets /Smoke/Missing, which does not exist"), std::string::npos);
    delegate.sceneDescription();
    ASSERT_EQ(warnings.size(), 2u);
    EXPECT_NE(warnings[1].find("1 volume is read but not rendered yet"), std::string::npos) << warnings[1];
}

}  // namespace
}  // namespace fluence::delegate
