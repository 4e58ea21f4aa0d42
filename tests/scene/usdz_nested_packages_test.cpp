// USDZ packages inside packages (issue #21), on OpenUSD's own test packages
// (tests/scene/data/usdz/README.md): a package whose root layer is another package composes the
// stage its loose source layers compose, with every layer read from inside the inner package,
// and a package of packages (combined.usdz) references each inner package's root layer and
// resolves, finds and extracts a texture stored two packages deep.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "scene/asset_path.h"
#include "scene/package_files.h"
#include "scene/stage.h"
#include "scene/usda_writer.h"
#include "scene/usdz_package.h"

namespace fluence::usd {
namespace {

namespace fs = std::filesystem;

const fs::path kData = fs::path(FLUENCE_SOURCE_DIR "/tests/scene/data/usdz").lexically_normal();

std::string flattened(const std::string& path) { return writeUsda(Stage::open(path)->composedLayer()); }

// OpenUSD's testUsdUsdzFileFormat: the nested packages, opened whole or at their inner package
// or its root layer, compose what anchored_refs/root.usd composes loose.
TEST(UsdzNestedPackages, ComposeTheStageOfTheirLooseSources) {
    const std::string expected = flattened((kData / "anchored_refs/root.usd").string());
    EXPECT_NE(expected.find("attr_usdc"), std::string::npos);  // every reference was followed
    const std::string nested = (kData / "nested_anchored_refs.usdz").string();
    for (const std::string& path :
         {nested, (kData / "nested_anchored_refs_sub.usdz").string(), packagePath(nested, "anchored_refs.usdz"),
          packagePath(packagePath(nested, "anchored_refs.usdz"), "root.usd")}) {
        SCOPED_TRACE(path);
        EXPECT_EQ(flattened(path), expected);
        EXPECT_TRUE(Stage::open(path)->warnings().empty());
    }
    // The layers are read from inside the inner package, each named by its nested path.
    std::vector<std::string> layers = Stage::open(nested)->layerFiles();
    const std::string inner = packagePath(nested, "anchored_refs.usdz");
    for (const char* entry : {"ref.usd", "sub/ref.usda", "sub/ref.usdc"}) {
        EXPECT_NE(std::find(layers.begin(), layers.end(), packagePath(inner, entry)), layers.end()) << entry;
    }
}

TEST(UsdzNestedPackages, PackageOfPackagesWithATextureTwoPackagesDeep) {
    const std::string combined = (kData / "combined.usdz").string();
    std::unique_ptr<Stage> stage = Stage::open(combined);
    EXPECT_TRUE(stage->warnings().empty());
    const PrimSpec* cube = stage->prim("/World/simpleMesh/Geom/cube");
    ASSERT_NE(cube, nullptr);
    EXPECT_EQ(cube->typeName, "Mesh");
    ASSERT_NE(cube->attribute("points"), nullptr);
    ASSERT_NE(stage->prim("/World/simpleMaterial/card"), nullptr);

    const PrimSpec* texture = stage->prim("/World/simpleMaterial/boardMat/diffuseTexture");
    ASSERT_NE(texture, nullptr);
    ASSERT_NE(texture->attribute("inputs:file"), nullptr);
    std::optional<Value> file = Stage::resolve(*texture->attribute("inputs:file"), 0.0);
    ASSERT_TRUE(file && !file->strings.empty());
    const std::string innerPackage = packagePath(combined, "combined.usdz_FILES/simpleMaterial.usdz");
    const std::string resolved = packagePath(innerPackage, "simpleMaterial.usdz_FILES/0/USDLogoLrg.png");
    EXPECT_EQ(file->strings[0], resolved);
    EXPECT_TRUE(assetExists(resolved));
    EXPECT_FALSE(assetExists(packagePath(innerPackage, "simpleMaterial.usdz_FILES/0/missing.png")));

    // Extracted for OpenImageIO: the PNG stored in the inner package, byte for byte.
    const UsdzPackage inner = UsdzPackage::open(innerPackage);
    std::string_view png = inner.bytes("simpleMaterial.usdz_FILES/0/USDLogoLrg.png");
    EXPECT_EQ(png.substr(0, 4), "\x89PNG");
    const std::string extracted = fileForAsset(resolved);
    EXPECT_NE(extracted, resolved);
    std::ifstream in(extracted, std::ios::binary);
    std::stringstream copy;
    copy << in.rdbuf();
    EXPECT_EQ(copy.str(), png);
}

}  // namespace
}  // namespace fluence::usd
