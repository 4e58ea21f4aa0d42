// `fluence render` of USDZ packages: the corpus's texture-cat-plane.usdz renders the same image as
// its entries copied out to loose files (its layer and textures/texture-cat.jpg), and that image
// depends on the packaged texture (without it the loose render differs), so the texture was read
// from the package (with the light moved off the plane: see litOver). Truncated or corrupted packages fail with exit code 4 and an error naming them.
// The corpus's own loose texture-cat-plane.usda/.usdc are another Blender export (other prims,
// camera and metersPerUnit), so they are not an image reference.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "scene/usdz_package.h"
#include "tests/support/cli.h"
#include "tests/support/shared_data.h"
#include "tests/support/temp_dir.h"

namespace fluence {
namespace {

namespace fs = std::filesystem;

const fs::path kPackage = test::sharedPath("usd_corpus/tinyusdz/models/texture-cat-plane.usdz");

test::RunResult render(const fs::path& scene, const fs::path& out, const test::TempDir& dir,
                       const std::string& options = "") {
    return test::runFluence("render '" + scene.string() + "' -o '" + out.string() + "' -r 48 32 --spp 4" + options,
                            dir.path());
}

// The largest difference between the beauty channels of two renders of one size.
float largestDifference(const test::ExrImage& a, const test::ExrImage& b) {
    float largest = 0.0f;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x)
            for (const char* c : {"R", "G", "B", "A"})
                largest = std::max(largest, std::abs(a.at(x, y, c) - b.at(x, y, c)));
    return largest;
}

// A layer over `scene` (a sublayer) that moves the package's light off the textured plane, where
// Blender exported it (at the plane's centre, radius 0: the plane renders black), so the texture
// shows.
fs::path litOver(const fs::path& scene, const test::TempDir& dir, const std::string& name) {
    const fs::path layer = dir.path() / name;
    std::ofstream(layer)
        << "#usda 1.0\n(\n    subLayers = [@" << scene.string() << "@]\n)\n"
        << "over \"root\" { over \"root\" { over \"lights\" { over \"environment\" {\n"
        << "    matrix4d xformOp:transform = ((1, 0, 0, 0), (0, 1, 0, 0), (0, 0, 1, 0), (0, -4, 0, 1))\n"
        << "    over \"environment\" {\n        float inputs:radius = 0.5\n    }\n}\n}\n}\n}\n";
    return layer;
}

TEST(UsdzCli, PackageRendersAsItsEntriesDoLoose) {
    FLUENCE_REQUIRE_SHARED(kPackage);
    test::TempDir dir;
    const usd::UsdzPackage package = usd::UsdzPackage::open(kPackage.string());
    for (const usd::UsdzPackage::Entry& entry : package.entries()) {
        fs::create_directories((dir.path() / "loose" / entry.name).parent_path());
        std::ofstream(dir.path() / "loose" / entry.name, std::ios::binary) << package.bytes(entry);
    }
    const fs::path looseLayer = dir.path() / "loose" / package.entries().front().name;
    const auto rendered = [&](const fs::path& scene, const std::string& name) {
        test::RunResult r = render(scene, dir.path() / name, dir);
        EXPECT_EQ(r.exitCode, 0) << r.err;
        EXPECT_EQ(r.err.find("not found"), std::string::npos) << r.err;
        return test::readExr(dir.path() / name);
    };
    test::ExrImage packaged = rendered(kPackage, "packaged.exr");
    EXPECT_EQ(largestDifference(packaged, rendered(looseLayer, "loose.exr")), 0.0f);

    test::ExrImage packagedLit = rendered(litOver(kPackage, dir, "packaged_lit.usda"), "packaged_lit.exr");
    EXPECT_EQ(largestDifference(packagedLit, rendered(litOver(looseLayer, dir, "loose_lit.usda"), "loose_lit.exr")),
              0.0f);
    fs::remove(dir.path() / "loose" / "textures" / "texture-cat.jpg");
    const fs::path untexturedScene = litOver(looseLayer, dir, "untextured.usda");
    EXPECT_EQ(render(untexturedScene, dir.path() / "untextured.exr", dir).exitCode, 4)
        << "a missing texture is an error";
    test::RunResult untextured = render(untexturedScene, dir.path() / "untextured.exr", dir, " --allow-missing");
    ASSERT_EQ(untextured.exitCode, 0) << untextured.err;
    EXPECT_GT(largestDifference(packagedLit, test::readExr(dir.path() / "untextured.exr")), 0.01f);
}

TEST(UsdzCli, DamagedPackagesFailNamingThem) {
    FLUENCE_REQUIRE_SHARED(kPackage);
    test::TempDir dir;
    const std::string bytes = test::slurp(kPackage);
    std::string compressed = bytes;
    compressed[compressed.find("PK\x01\x02") + 10] = 8;  // the root layer's entry marked deflated
    for (const auto& [name, content, what] : {std::tuple<std::string, std::string, std::string>{
                                                  "truncated.usdz", bytes.substr(0, bytes.size() / 2), "truncated"},
                                              {"compressed.usdz", compressed, "compressed"}}) {
        SCOPED_TRACE(name);
        const fs::path scene = dir.path() / name;
        std::ofstream(scene, std::ios::binary) << content;
        test::RunResult r = render(scene, dir.path() / "out.exr", dir);
        EXPECT_EQ(r.exitCode, 4) << r.err;
        EXPECT_NE(r.err.find(scene.string()), std::string::npos) << r.err;
        EXPECT_NE(r.err.find(what), std::string::npos) << r.err;
        EXPECT_FALSE(fs::exists(dir.path() / "out.exr"));
    }
}

// A texture entry stored compressed (USDZ requires stored entries) is a missing asset named by
// Fluence, with the package, the entry and why: exit 4, and --allow-missing renders with the
// texture's fallback.
TEST(UsdzCli, ACompressedTextureEntryIsAMissingAssetSayingWhy) {
    FLUENCE_REQUIRE_SHARED(kPackage);
    test::TempDir dir;
    std::string bytes = test::slurp(kPackage);
    const std::string entry = "textures/texture-cat.jpg";
    const std::size_t name = bytes.rfind(entry);  // in the central directory, the archive's last part
    ASSERT_NE(name, std::string::npos);
    const std::size_t record = name - 46;  // a central directory entry's fixed part precedes its name
    ASSERT_EQ(bytes.compare(record, 4, "PK\x01\x02"), 0);
    bytes[record + 10] = 8;  // marked deflated
    const fs::path scene = dir.path() / "compressed_texture.usdz";
    std::ofstream(scene, std::ios::binary) << bytes;
    test::RunResult r = render(scene, dir.path() / "out.exr", dir);
    EXPECT_EQ(r.exitCode, 4) << r.err;
    EXPECT_NE(r.err.find("'" + scene.string() + "': entry '" + entry +
                         "' is compressed (zip method 8); USDZ entries must be stored"),
              std::string::npos)
        << r.err;
    EXPECT_FALSE(fs::exists(dir.path() / "out.exr"));
    r = render(scene, dir.path() / "out.exr", dir, " --allow-missing");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("is compressed (zip method 8)"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("cannot read texture"), std::string::npos) << "OpenImageIO is not asked:\n" << r.err;
    EXPECT_TRUE(fs::exists(dir.path() / "out.exr"));
}

// Packages inside packages from the command line (OpenUSD's test packages, tests/scene/data/usdz):
// a package-relative path naming an inner package opens as that package's root layer, and
// combined.usdz renders with its texture found two packages deep (a missing one exits 4).
TEST(UsdzCli, NestedPackagesOpenAndRender) {
    test::TempDir dir;
    const fs::path data = fs::path(FLUENCE_SOURCE_DIR "/tests/scene/data/usdz").lexically_normal();
    const std::string inner = usd::packagePath((data / "nested_anchored_refs.usdz").string(), "anchored_refs.usdz");
    test::RunResult info = test::runFluence("info '" + inner + "'", dir.path());
    EXPECT_EQ(info.exitCode, 0) << info.err;
    EXPECT_NE(info.out.find("  " + usd::packagePath(inner, "sub/ref.usdc") + "\n"), std::string::npos) << info.out;
    EXPECT_NE(info.out.find("Model"), std::string::npos) << info.out;

    const std::string combined = (data / "combined.usdz").string();
    info = test::runFluence("info '" + combined + "'", dir.path());
    EXPECT_EQ(info.exitCode, 0) << info.err;
    const std::string texture = usd::packagePath(usd::packagePath(combined, "combined.usdz_FILES/simpleMaterial.usdz"),
                                                 "simpleMaterial.usdz_FILES/0/USDLogoLrg.png");
    EXPECT_NE(info.out.find("ok       " + texture), std::string::npos) << info.out;
    test::RunResult r = render(combined, dir.path() / "combined.exr", dir);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(fs::exists(dir.path() / "combined.exr"));
}

// OpenUSD's testUsdUsdzFileFormat search_refs packages (tests/scene/data/usdz/README.md): a
// search-relative reference inside a package ("sub/x.usd", no "./") resolves beside the layer that
// authors it, else beside the package's root layer, so every package flattens to what OpenUSD's
// test expects (the loose root.usd composed with search_refs/ as the search path), with no warning.
TEST(UsdzCli, SearchRelativePathsResolveInsideThePackage) {
    test::TempDir dir;
    const fs::path data = fs::path(FLUENCE_SOURCE_DIR "/tests/scene/data/usdz").lexically_normal();
    const std::string expected =
        "#usda 1.0\n\ndef \"Model\"\n{\n"
        "    string attr_in_both = \"right_attr_in_both\"\n"  // beside refs/ref.usd, not the root's
        "    string attr_in_root = \"attr_in_root\"\n"        // only beside the root layer
        "    string attr_in_subdir = \"attr_in_subdir\"\n"
        "    string attr_usd = \"usd\"\n}\n";
    for (const char* package :
         {"search_refs.usdz", "search_refs_sub.usdz", "nested_search_refs.usdz", "nested_search_refs_sub.usdz"}) {
        SCOPED_TRACE(package);
        const test::RunResult r = test::runFluence("cat --flatten '" + (data / package).string() + "'", dir.path());
        EXPECT_EQ(r.exitCode, 0) << r.err;
        EXPECT_EQ(r.err, "");
        EXPECT_EQ(r.out, expected);
    }
}

}  // namespace
}  // namespace fluence
