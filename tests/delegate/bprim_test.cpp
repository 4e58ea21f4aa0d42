// Bprims: the OpenVDB field assets volumes name and the textures materials use enter the render
// index as their own prims, synced from dirty bits (loading the files is the volume and texture
// issues' work).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "delegate/scene_delegate.h"
#include "scene/usda_parser.h"
#include "tests/support/temp_dir.h"

namespace fluence::delegate {
namespace {

struct Indexed {
    std::unique_ptr<usd::Stage> stage;
    std::vector<std::string> warnings;
    std::unique_ptr<SceneDelegate> delegate;

    explicit Indexed(const std::string& usda, const std::string& file = "scene.usda")
        : stage(std::make_unique<usd::Stage>(usd::parseUsdaString(usda, file))) {
        DelegateOptions options;
        options.convertColor = [](const RGB& c, const std::string&) { return c; };
        options.warn = [this](const std::string& path, const std::string& message) {
            warnings.push_back(path + ": " + message);
        };
        delegate = std::make_unique<SceneDelegate>(*stage, options);
        delegate->sync();
    }
    template <typename T>
    const T& prim(const std::string& path) const {
        const auto* p = dynamic_cast<const T*>(delegate->renderIndex().find(path));
        if (!p) throw std::runtime_error("no such render prim: " + path);
        return *p;
    }
};

const char* kVolume = R"(#usda 1.0
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
)";

TEST(Bprims, VolumeFieldsAreFieldBprims) {
    Indexed index(kVolume);
    const auto& volume = index.prim<VolumeRprim>("/Smoke");
    ASSERT_EQ(volume.fields().size(), 1u);
    EXPECT_EQ(volume.fields()[0].name, "density");
    EXPECT_EQ(volume.fields()[0].assetPrim, "/Smoke/Density");
    const auto& field = index.prim<FieldBprim>("/Smoke/Density");
    EXPECT_EQ(field.filePath(), "/data/smoke.vdb");
    EXPECT_EQ(field.gridName(), "density");
    EXPECT_EQ(field.fieldIndex(), 0);
    EXPECT_FALSE(field.fileFound());
    ASSERT_EQ(index.warnings.size(), 1u);
    EXPECT_NE(index.warnings[0].find("field 'temperature' targets /Smoke/Missing, which does not exist"),
              std::string::npos);
    try {
        index.delegate->sceneDescription();
        ADD_FAILURE() << "a missing OpenVDB file must fail the render";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("/Smoke: field 'density': OpenVDB file /data/smoke.vdb not found"),
                  std::string::npos)
            << e.what();
    }
}

TEST(Bprims, EditingAFieldAssetResyncsOnlyThatField) {
    Indexed index(kVolume);
    index.delegate->setAttribute("/Smoke/Density", "fieldName",
                                 usd::Value::string("token", usd::ValueKind::Token, {"heat"}, false));
    EXPECT_EQ(index.delegate->sync(), 1u);
    EXPECT_EQ(index.prim<FieldBprim>("/Smoke/Density").gridName(), "heat");
    EXPECT_EQ(index.prim<VolumeRprim>("/Smoke").syncCount(), 1);
}

TEST(Bprims, MaterialTexturesAreTextureBprimsAndEditsResyncOnlyThem) {
    test::TempDir dir{"fluence_bprims"};
    std::ofstream(dir.path() / "wood.png") << "not read yet";
    std::ofstream(dir.path() / "tiles.1003.exr") << "not read yet";
    Indexed index(R"(#usda 1.0
def Camera "Cam"
{
}
def Mesh "Floor" (
    prepend apiSchemas = ["MaterialBindingAPI"]
)
{
    int[] faceVertexCounts = [3]
    int[] faceVertexIndices = [0, 1, 2]
    point3f[] points = [(0, 0, 0), (1, 0, 0), (0, 1, 0)]
    rel material:binding = </Looks/Wood>
}
def Scope "Looks"
{
    def Material "Wood"
    {
        token outputs:surface.connect = </Looks/Wood/Surface.outputs:surface>
        def Shader "Surface"
        {
            uniform token info:id = "UsdPreviewSurface"
            color3f inputs:diffuseColor.connect = </Looks/Wood/Grain.outputs:rgb>
            token outputs:surface
        }
        def Shader "Grain"
        {
            uniform token info:id = "UsdUVTexture"
            asset inputs:file = @./wood.png@
            token inputs:sourceColorSpace = "sRGB"
            token inputs:wrapS = "repeat"
            float3 outputs:rgb
        }
        def Shader "Tiles"
        {
            uniform token info:id = "UsdUVTexture"
            asset inputs:file = @./tiles.<UDIM>.exr@
        }
        def Shader "Lost"
        {
            uniform token info:id = "UsdUVTexture"
            asset inputs:file = @./lost.png@
        }
    }
}
)",
                  (dir.path() / "scene.usda").string());
    const auto& grain = index.prim<TextureBprim>("/Looks/Wood/Grain");
    EXPECT_EQ(grain.filePath(), (dir.path() / "wood.png").string());
    EXPECT_EQ(grain.sourceColorSpace(), "sRGB");
    EXPECT_EQ(grain.wrapS(), "repeat");
    EXPECT_EQ(grain.wrapT(), "useMetadata");
    EXPECT_TRUE(grain.fileFound());
    EXPECT_TRUE(index.prim<TextureBprim>("/Looks/Wood/Tiles").fileFound()) << "UDIM tile 1003 exists";
    EXPECT_FALSE(index.prim<TextureBprim>("/Looks/Wood/Lost").fileFound());
    EXPECT_EQ(index.prim<MaterialSprim>("/Looks/Wood").textures().size(), 3u);

    index.delegate->setAttribute(
        "/Looks/Wood/Grain", "inputs:file",
        usd::Value::string("asset", usd::ValueKind::Asset, {(dir.path() / "gone.png").string()}, false));
    EXPECT_EQ(index.delegate->sync(), 1u) << "only the texture";
    EXPECT_FALSE(grain.fileFound());
    EXPECT_EQ(index.prim<MaterialSprim>("/Looks/Wood").syncCount(), 1);
    EXPECT_EQ(index.prim<MeshRprim>("/Floor").dataReads(), 1);
}

}  // namespace
}  // namespace fluence::delegate
