// USDZ packages (scene/usdz_package.h): the corpus packages open and their root layers read as
// their entries do copied out to loose files; asset paths authored in a packaged layer resolve
// inside the package, where sublayers load from and textures are extracted for OpenImageIO
// (scene/package_files.h); damaged packages (truncated, compressed, encrypted, zip64, offsets out
// of range) throw FileError naming the package, never read out of bounds.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "scene/asset_path.h"
#include "scene/layer_file.h"
#include "scene/package_files.h"
#include "scene/stage.h"
#include "scene/usda_parser.h"
#include "scene/usda_writer.h"
#include "scene/usdz_package.h"
#include "tests/support/shared_data.h"
#include "tests/support/temp_dir.h"

namespace fluence::usd {
namespace {

namespace fs = std::filesystem;

const fs::path kModels = test::sharedPath("usd_corpus/tinyusdz/models");

std::string slurp(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

void put(std::string& out, std::uint32_t value, int bytes) {
    for (int i = 0; i < bytes; ++i) out.push_back(static_cast<char>(value >> (8 * i) & 0xFF));
}

// A stored (uncompressed) zip archive of `files`, in order; CRCs are left zero (not checked).
// The entries named in `deflated` are marked deflated (method 8), their bytes kept as given.
std::string zipOf(const std::vector<std::pair<std::string, std::string>>& files,
                  const std::vector<std::string>& deflated = {}) {
    std::string archive, directory;
    for (const auto& [name, data] : files) {
        std::uint32_t offset = static_cast<std::uint32_t>(archive.size());
        const std::uint32_t method = std::find(deflated.begin(), deflated.end(), name) != deflated.end() ? 8 : 0;
        put(archive, 0x04034b50, 4), put(archive, 20, 2), put(archive, 0, 2), put(archive, method, 2);
        put(archive, 0, 4), put(archive, 0, 4), put(archive, std::uint32_t(data.size()), 4),
            put(archive, std::uint32_t(data.size()), 4);
        put(archive, std::uint32_t(name.size()), 2), put(archive, 0, 2);
        archive += name + data;
        put(directory, 0x02014b50, 4), put(directory, 20, 2), put(directory, 20, 2), put(directory, 0, 2),
            put(directory, method, 2);
        put(directory, 0, 4), put(directory, 0, 4), put(directory, std::uint32_t(data.size()), 4),
            put(directory, std::uint32_t(data.size()), 4);
        put(directory, std::uint32_t(name.size()), 2), put(directory, 0, 2), put(directory, 0, 2), put(directory, 0, 2);
        put(directory, 0, 2), put(directory, 0, 4), put(directory, offset, 4);
        directory += name;
    }
    std::uint32_t directoryOffset = static_cast<std::uint32_t>(archive.size());
    archive += directory;
    put(archive, 0x06054b50, 4), put(archive, 0, 2), put(archive, 0, 2);
    put(archive, std::uint32_t(files.size()), 2), put(archive, std::uint32_t(files.size()), 2);
    put(archive, std::uint32_t(directory.size()), 4), put(archive, directoryOffset, 4), put(archive, 0, 2);
    return archive;
}

std::string write(const test::TempDir& dir, const std::string& name, const std::string& bytes) {
    std::ofstream(dir.file(name), std::ios::binary) << bytes;
    return dir.file(name);
}

TEST(UsdzPackage, CorpusPackagesOpenWithTheirEntries) {
    FLUENCE_REQUIRE_SHARED(kModels);
    UsdzPackage cube = UsdzPackage::open((kModels / "cube.usdz").string());
    ASSERT_EQ(cube.entries().size(), 1u);
    EXPECT_EQ(cube.entries()[0].name, "cube.usdc");
    EXPECT_EQ(cube.bytes("cube.usdc").substr(0, 8), "PXR-USDC");

    UsdzPackage cat = UsdzPackage::open((kModels / "texture-cat-plane.usdz").string());
    ASSERT_EQ(cat.entries().size(), 2u);
    EXPECT_EQ(cat.entries()[0].name, "texture-cat-plane.usdc");
    EXPECT_EQ(cat.bytes("textures/texture-cat.jpg"), slurp(kModels / "textures/texture-cat.jpg"));
    EXPECT_THROW(cat.bytes("textures/missing.png"), FileError);
}

// The corpus's loose cube.usdc and texture-cat-plane.usdc/.usda are other Blender exports than
// the packaged layers (other prims and metadata), so each root layer is compared, as the USDA text
// it writes, with its own entry copied out to a loose file.
TEST(UsdzPackage, RootLayersReadAsTheirEntriesDoLoose) {
    FLUENCE_REQUIRE_SHARED(kModels);
    test::TempDir dir;
    for (const char* name : {"cube", "texture-cat-plane"}) {
        SCOPED_TRACE(name);
        const std::string package = (kModels / (std::string(name) + ".usdz")).string();
        const std::string entry = std::string(name) + ".usdc";
        std::unique_ptr<Layer> packaged = readLayerFile(package);
        EXPECT_EQ(packaged->identifier, packagePath(package, entry));
        EXPECT_FALSE(packaged->rootPrims.empty());
        std::unique_ptr<Layer> loose =
            readLayerFile(write(dir, entry, std::string(UsdzPackage::open(package).bytes(entry))));
        EXPECT_EQ(writeUsda(*packaged), writeUsda(*loose));
        EXPECT_EQ(writeUsda(*readLayerFile(packagePath(package, entry))), writeUsda(*loose));
    }
}

TEST(UsdzPackage, TexturePathsResolveInsideThePackageAndExtract) {
    FLUENCE_REQUIRE_SHARED(kModels);
    const std::string package = (kModels / "texture-cat-plane.usdz").generic_string();
    std::unique_ptr<Stage> stage = Stage::open(package);
    const PrimSpec* shader = stage->prim("/root/_materials/Material_001/Image_Texture");
    ASSERT_NE(shader, nullptr);
    const AttributeSpec* file = shader->attribute("inputs:file");
    ASSERT_NE(file, nullptr);
    std::optional<Value> value = Stage::resolve(*file, 0.0);
    ASSERT_TRUE(value && !value->strings.empty());
    const std::string resolved = value->strings[0];
    EXPECT_EQ(resolved, packagePath(package, "textures/texture-cat.jpg"));
    EXPECT_TRUE(assetExists(resolved));
    EXPECT_FALSE(assetExists(packagePath(package, "textures/missing.jpg")));

    const std::string extracted = fileForAsset(resolved);
    EXPECT_NE(extracted, resolved);
    EXPECT_EQ(fs::path(extracted).filename(), "texture-cat.jpg");
    EXPECT_EQ(slurp(extracted), slurp(kModels / "textures/texture-cat.jpg"));
    EXPECT_EQ(fileForAsset(resolved), extracted);  // extracted once, then reused
    EXPECT_EQ(fileForAsset("/no/such.usdz[a.png]"), "/no/such.usdz[a.png]");
    EXPECT_EQ(fileForAsset("/plain/file.png"), "/plain/file.png");
}

TEST(UsdzPackage, NestedLayersLoadFromThePackage) {
    test::TempDir dir;
    const std::string root =
        "#usda 1.0\n(\n    subLayers = [@./layers/geom.usda@]\n)\n"
        "def Xform \"World\" (references = @./layers/ref.usda@</Thing>)\n{\n}\n";
    const std::string geom = "#usda 1.0\ndef Sphere \"Ball\"\n{\n    asset tex = @../tex/a.png@\n}\n";
    const std::string ref = "#usda 1.0\ndef Cube \"Thing\"\n{\n    double size = 3\n}\n";
    const std::string package =
        write(dir, "scene.usdz",
              zipOf({{"root.usda", root}, {"layers/geom.usda", geom}, {"layers/ref.usda", ref}, {"tex/a.png", "png"}}));
    std::unique_ptr<Stage> stage = Stage::open(package);
    ASSERT_NE(stage->prim("/Ball"), nullptr);
    const PrimSpec* world = stage->prim("/World");
    ASSERT_NE(world, nullptr);
    EXPECT_EQ(world->typeName, "Xform");  // the referencing layer's opinion is stronger
    ASSERT_NE(world->attribute("size"), nullptr);
    std::optional<Value> tex = Stage::resolve(*stage->prim("/Ball")->attribute("tex"), 0.0);
    ASSERT_TRUE(tex && !tex->strings.empty());
    EXPECT_EQ(tex->strings[0], packagePath(normalizedAbsolutePath(package), "tex/a.png"));
    EXPECT_EQ(slurp(fileForAsset(tex->strings[0])), "png");
}

TEST(UsdzPackage, FirstEntryMustBeALayer) {
    test::TempDir dir;
    const std::string package = write(dir, "image.usdz", zipOf({{"a.png", "png"}}));
    EXPECT_THROW(readLayerFile(package), FileError);
    EXPECT_THROW(readLayerFile(write(dir, "empty.usdz", zipOf({}))), FileError);
}

// Throws FileError whose message names `path` and holds `what`.
void expectRejected(const std::string& path, const std::string& what) {
    try {
        readLayerFile(path);
        ADD_FAILURE() << path << " was read";
    } catch (const FileError& e) {
        EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
}

TEST(UsdzPackage, DamagedPackagesAreRejectedNamingThem) {
    test::TempDir dir;
    const std::string good = zipOf({{"root.usda", "#usda 1.0\ndef \"A\"\n{\n}\n"}, {"tex.png", "png"}});
    std::string bytes;

    expectRejected(write(dir, "empty.usdz", ""), "not a zip archive");
    expectRejected(write(dir, "text.usdz", "#usda 1.0\n"), "not a zip archive");
    for (std::size_t cut : {good.size() - 1, good.size() / 2, std::size_t(31)})
        expectRejected(write(dir, "cut" + std::to_string(cut) + ".usdz", good.substr(0, cut)), "truncated?");

    const std::size_t directory = good.find("PK\x01\x02");
    const std::size_t end = good.find("PK\x05\x06");
    bytes = good, bytes[directory + 10] = 8;  // deflate
    expectRejected(write(dir, "deflated.usdz", bytes), "entry 'root.usda' is compressed");
    bytes = good, bytes[directory + 8] = 1;  // encrypted
    expectRejected(write(dir, "encrypted.usdz", bytes), "entry 'root.usda' is encrypted");
    bytes = good, bytes[end + 10] = bytes[end + 11] = '\xFF';
    expectRejected(write(dir, "zip64.usdz", bytes), "zip64");
    bytes = good, bytes[end + 19] = '\x7F';  // directory offset far past the end
    expectRejected(write(dir, "offset.usdz", bytes), "central directory lies outside");
    bytes = good, bytes[directory + 45] = '\x7F';  // local header offset past the end
    expectRejected(write(dir, "local.usdz", bytes), "truncated zip archive");
    bytes = good, bytes[directory + 23] = bytes[directory + 27] = '\x7F';  // entry size past the end
    expectRejected(write(dir, "size.usdz", bytes), "entry 'root.usda' runs past the end");
    bytes = good, bytes[directory + 27] = '\x7F';
    expectRejected(write(dir, "sizes.usdz", bytes), "stored size unlike its size");
    bytes = good, bytes[directory + 28] = '\x7F';  // name runs past the directory
    expectRejected(write(dir, "name.usdz", bytes), "runs past the directory");
    expectRejected(dir.file("missing.usdz"), "cannot open");
}

// As OpenUSD's usdz resolver: a package whose root layer is stored opens although other entries
// are compressed; reading a compressed entry (a referenced layer, a texture) fails naming the
// package and the entry, and only that.
TEST(UsdzPackage, CompressedEntriesFailOnlyWhenRead) {
    test::TempDir dir;
    const std::string root =
        "#usda 1.0\ndef Sphere \"Ball\"\n{\n    asset tex = @./tex.png@\n}\n"
        "def \"Packed\" (references = @./packed.usda@</Thing>)\n{\n}\n";
    const std::string package = write(
        dir, "mixed.usdz",
        zipOf({{"root.usda", root}, {"tex.png", "\x78\x9c deflated bytes"}, {"packed.usda", "\x78\x9c deflated bytes"}},
              {"tex.png", "packed.usda"}));
    std::unique_ptr<Stage> stage;
    ASSERT_NO_THROW(stage = Stage::open(package));
    ASSERT_NE(stage->prim("/Ball"), nullptr);
    bool warned = false;
    for (const CompositionWarning& warning : stage->warnings())
        warned |= warning.message.find("entry 'packed.usda' is compressed") != std::string::npos;
    EXPECT_TRUE(warned) << "no warning names the compressed layer";

    UsdzPackage opened = UsdzPackage::open(package);
    EXPECT_EQ(opened.bytes("root.usda"), root);
    auto expectCompressed = [&](const std::function<void()>& read, const std::string& entry) {
        try {
            read();
            ADD_FAILURE() << "the compressed entry " << entry << " was read";
        } catch (const FileError& e) {
            EXPECT_NE(std::string(e.what()).find("'" + package + "'"), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("entry '" + entry + "' is compressed (zip method 8)"),
                      std::string::npos)
                << e.what();
        }
    };
    expectCompressed([&] { opened.bytes("tex.png"); }, "tex.png");
    expectCompressed([&] { readLayerFile(packagePath(package, "packed.usda")); }, "packed.usda");
    // A compressed entry cannot be read, so as an asset it is missing (the CLI names the entry and
    // why: UsdzCli.ACompressedTextureEntryIsAMissingAssetSayingWhy); it is never extracted.
    const std::string texture = packagePath(normalizedAbsolutePath(package), "tex.png");
    EXPECT_FALSE(assetExists(texture));
    EXPECT_EQ(fileForAsset(texture), texture);
}

TEST(UsdzPackage, PackagePathSyntax) {
    EXPECT_EQ(packagePath("/a/b.usdz", "t/c.png"), "/a/b.usdz[t/c.png]");
    std::optional<PackagePath> split = splitPackagePath("/a/b.usdz[t/c.png]");
    ASSERT_TRUE(split);
    EXPECT_EQ(split->package, "/a/b.usdz");
    EXPECT_EQ(split->entry, "t/c.png");
    EXPECT_FALSE(splitPackagePath("/a/b.png"));
    EXPECT_FALSE(splitPackagePath("/a/b.usdz[]"));
    EXPECT_EQ(anchorAssetPath("/a/b.usdz[dir/root.usda]", "./t.png"), "/a/b.usdz[dir/t.png]");
    EXPECT_EQ(anchorAssetPath("/a/b.usdz[root.usda]", "/abs/t.png"), "/abs/t.png");
    EXPECT_TRUE(isUsdzPath("X.USDZ"));

    // Packages nest: the outer split names the file, the inner one the innermost package.
    EXPECT_EQ(packagePath("/a/b.usdz[c.usdz]", "t/d.png"), "/a/b.usdz[c.usdz[t/d.png]]");
    split = splitPackagePath("/a/b.usdz[c.usdz[t/d.png]]");
    ASSERT_TRUE(split);
    EXPECT_EQ(split->package, "/a/b.usdz");
    EXPECT_EQ(split->entry, "c.usdz[t/d.png]");
    split = splitInnermostPackagePath("/a/b.usdz[c.usdz[t/d.png]]");
    ASSERT_TRUE(split);
    EXPECT_EQ(split->package, "/a/b.usdz[c.usdz]");
    EXPECT_EQ(split->entry, "t/d.png");
    EXPECT_FALSE(splitInnermostPackagePath("/a/b.png"));
    EXPECT_EQ(anchorAssetPath("/a/b.usdz[c.usdz[dir/root.usda]]", "./t.png"), "/a/b.usdz[c.usdz[dir/t.png]]");
    EXPECT_EQ(anchorAssetPath("/a/b.usdz[c.usdz[dir/root.usda]]", "../t.png"), "/a/b.usdz[c.usdz[t.png]]");
    EXPECT_TRUE(isUsdzPath("/a/b.usdz[c.USDZ]"));
    EXPECT_FALSE(isUsdzPath("/a/b.usdz[c.png]"));
    std::string deep = "a.usdz";
    for (int i = 0; i < 100; ++i) deep += "[b.usdz";
    deep += std::string(100, ']');
    EXPECT_THROW(isUsdzPath(deep), FileError);  // nested past 64 packages
}

}  // namespace
}  // namespace fluence::usd
