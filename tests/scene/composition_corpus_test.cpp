// Composition on the real-world corpus in shared/usd_corpus (skipped when it is absent): every
// valid text layer opens through Stage::open, and two production-style assets compose to the
// prims, values and warnings read off their files by hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <string>
#include <vector>

#include "scene/stage.h"
#include "scene/usda_parser.h"
#include "tests/support/shared_data.h"

namespace fluence::usd {
namespace {

namespace fs = std::filesystem;

const fs::path kCorpus = test::sharedPath("usd_corpus");

bool isCrate(const fs::path& path) {
    std::ifstream file(path, std::ios::binary);
    char magic[8] = {};
    file.read(magic, sizeof magic);
    return std::string(magic, static_cast<std::size_t>(file.gcount())) == "PXR-USDC";
}

// OpenUSD's rule for its parser tests: a file with "_bad_" in its name must fail to load; usdview's
// invalidSyntax.usda is broken on purpose too.
bool isInvalidOnPurpose(const fs::path& path) {
    std::string name = path.filename().string();
    return name.find("_bad_") != std::string::npos || name == "invalidSyntax.usda";
}

std::string corpusFile(const std::string& relative) { return (kCorpus / relative).generic_string(); }

std::unique_ptr<Stage> timedOpen(const std::string& relative) {
    auto start = std::chrono::steady_clock::now();
    auto stage = Stage::open(corpusFile(relative));
    double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    std::cout << "[ compose  ] " << fs::path(relative).filename().string() << ": " << ms << " ms, "
              << stage->layerFiles().size() << " layers\n";
    return stage;
}

const PrimSpec& at(const Stage& stage, const std::string& path) {
    const PrimSpec* prim = stage.prim(path);
    if (!prim) throw std::runtime_error("no composed prim at " + path);
    return *prim;
}

std::optional<Value> value(const Stage& stage, const std::string& prim, const std::string& name) {
    const AttributeSpec* a = at(stage, prim).attribute(name);
    return a ? Stage::resolve(*a, kDefaultTime) : std::nullopt;
}

std::string allWarnings(const Stage& stage) {
    std::string all;
    for (const CompositionWarning& w : stage.warnings())
        all += w.location.str() + " " + w.primPath + ": " + w.message + "\n";
    return all;
}

TEST(CompositionCorpus, EveryValidLayerComposes) {
    FLUENCE_REQUIRE_SHARED(kCorpus);
    int composed = 0;
    std::size_t warnings = 0;
    for (const auto& entry : fs::recursive_directory_iterator(kCorpus)) {
        std::string extension = entry.path().extension().string();
        if (extension != ".usda" && extension != ".usd" && extension != ".sdf") continue;
        if (isInvalidOnPurpose(entry.path()) || (isCrate(entry.path()) && entry.path().filename() == "corrupt.usd"))
            continue;
        try {
            auto stage = Stage::open(entry.path().string());
            ++composed;
            warnings += stage->warnings().size();
        } catch (const std::exception& error) {
            ADD_FAILURE() << entry.path() << ": " << error.what();
        }
    }
    std::cout << "[ corpus   ] " << composed << " text layers composed, " << warnings << " warnings\n";
    EXPECT_GE(composed, 120);
}

TEST(CompositionCorpus, SpinningPyramids) {
    FLUENCE_REQUIRE_SHARED(kCorpus);
    auto stage = timedOpen("usd-wg-assets/full_assets/SubdivisionSurfaces/Creases_SpinningPyramids.usda");
    EXPECT_TRUE(stage->warnings().empty()) << allWarnings(*stage);
    EXPECT_EQ(stage->layerFiles().size(), 5u);  // the scene, Pyramid.usd, payload, mtl, geo
    EXPECT_EQ(at(*stage, "/World/Camera").typeName, "Camera");

    const std::string dir = corpusFile("usd-wg-assets/full_assets/SubdivisionSurfaces/Pyramid");
    std::set<std::string> keys;
    for (const char* name : {"Pyramid_NoCreases", "Pyramid_EdgeCreases", "Pyramid_CornerCreases"}) {
        std::string root = std::string("/World/") + name;
        const PrimSpec& pyramid = at(*stage, root);
        EXPECT_EQ(pyramid.typeName, "Xform");  // from Pyramid.usd; the scene's `def` has no type
        EXPECT_EQ(findMetadata(pyramid.metadata, "kind")->value.asString(), "component");
        const Value* identifier = findMetadata(pyramid.metadata, "assetInfo")->value.find("identifier");
        ASSERT_NE(identifier, nullptr);
        EXPECT_EQ(identifier->asString(), dir + "/Pyramid.usd");
        EXPECT_EQ(pyramid.attribute("xformOp:transform:xform1")->timeSamples.size(), 193u);
        // The variant "geo" (quad_creases, selected in Pyramid.usd) of geo.usda, through the payload.
        const PrimSpec& shape = at(*stage, root + "/geo/shape");
        EXPECT_EQ(shape.typeName, "Mesh");
        EXPECT_EQ(value(*stage, root + "/geo/shape", "subdivisionScheme")->asString(), "catmullClark");
        EXPECT_EQ(value(*stage, root + "/geo/shape", "faceVertexCounts")->size(), 24u);
        // mtl.usda's binding (authored in its "mtl" variant) and shader network, remapped twice.
        EXPECT_EQ(shape.relationship("material:binding")->targets,
                  (std::vector<std::string>{root + "/mtl/PyramidMaterial"}));
        EXPECT_EQ(at(*stage, root + "/mtl/PyramidMaterial").attribute("outputs:surface")->connections,
                  (std::vector<std::string>{root + "/mtl/PyramidMaterial/usdpreviewsurface1.outputs:surface"}));
        EXPECT_EQ(value(*stage, root + "/mtl/PyramidMaterial/usdpreviewsurface1", "inputs:roughness")->asDouble(),
                  0.1625);
        const MetadataEntry* key = findMetadata(pyramid.metadata, "fluence:instancePrototype");
        ASSERT_NE(key, nullptr);
        keys.insert(*key->value.asString());
    }
    EXPECT_EQ(keys.size(), 3u);  // three crease selections, three prototypes
    // The nested "creases" variant set picks the crease data.
    EXPECT_EQ(value(*stage, "/World/Pyramid_EdgeCreases/geo/shape", "creaseIndices")->numbers,
              (std::vector<double>{0, 2, 0, 1, 1, 3, 1, 2, 0, 3, 2, 3}));
    EXPECT_EQ(value(*stage, "/World/Pyramid_CornerCreases/geo/shape", "cornerIndices")->numbers,
              (std::vector<double>{0, 2}));
    EXPECT_EQ(at(*stage, "/World/Pyramid_NoCreases/geo/shape").attribute("creaseIndices"), nullptr);
    EXPECT_EQ(at(*stage, "/World/Pyramid_NoCreases/geo/shape").attribute("cornerIndices"), nullptr);
    // The referenced layers' own root prims are not part of the stage.
    EXPECT_EQ(stage->prim("/ASSET_geo_variant_0"), nullptr);
    EXPECT_EQ(stage->prim("/__class__"), nullptr);
}

TEST(CompositionCorpus, StandardShaderBall) {
    FLUENCE_REQUIRE_SHARED(kCorpus);
    auto stage = timedOpen("usd-wg-assets/full_assets/StandardShaderBall/standard_shader_ball_scene.usda");
    // The only warnings: the MaterialX documents the corpus leaves out (its README), referenced by
    // the selected "OpenPBRSurface" variant of example_materials.usda.
    ASSERT_EQ(stage->warnings().size(), 4u) << allWarnings(*stage);
    for (const char* name : {"plastic", "gold", "glass", "bubblegum"}) {
        std::string missing = corpusFile(
            std::string("usd-wg-assets/full_assets/StandardShaderBall/example_materials/") + name + "_openpbr.mtlx");
        auto it = std::find_if(stage->warnings().begin(), stage->warnings().end(), [&](const CompositionWarning& w) {
            return w.message.find("cannot find '" + missing + "'") != std::string::npos;
        });
        ASSERT_NE(it, stage->warnings().end()) << missing;
        EXPECT_EQ(it->primPath, "/standard_shader_ball_scene/materials/examples/mtlx");
        EXPECT_EQ(it->location.file,
                  corpusFile("usd-wg-assets/full_assets/StandardShaderBall/layers/example_materials.usda"));
    }
    EXPECT_EQ(stage->layerFiles().size(), 6u);  // 4 sublayers and the subdiv geometry
    EXPECT_EQ(stage->metersPerUnit(), 0.01);
    EXPECT_EQ(stage->defaultPrim(), "standard_shader_ball_scene");

    const std::string scene = "/standard_shader_ball_scene";
    EXPECT_EQ(at(*stage, scene + "/camera").typeName, "Camera");
    EXPECT_EQ(value(*stage, scene + "/camera", "focalLength")->asDouble(), 50.0);
    EXPECT_EQ(at(*stage, scene + "/lights/emitterTop/light0").typeName, "RectLight");
    EXPECT_EQ(value(*stage, scene + "/lights/emitterTop/light0", "inputs:intensity")->asDouble(), 6.0);
    // The "subdiv" variant references subdiv.usda (its defaultPrim, an `over`).
    EXPECT_EQ(at(*stage, scene + "/shader_ball/material_surface").typeName, "Mesh");
    EXPECT_EQ(value(*stage, scene + "/shader_ball/material_surface", "subdivisionScheme")->asString(), "catmullClark");
    EXPECT_EQ(value(*stage, scene + "/shader_ball/material_surface", "faceVertexCounts")->size(), 5838u);
    EXPECT_EQ(at(*stage, scene + "/shader_ball/neutral_objects/core").relationship("material:binding")->targets,
              (std::vector<std::string>{scene + "/materials/neutral"}));
    // Material "instances" by internal reference to box_base, with their own texture.
    const PrimSpec& back = at(*stage, scene + "/materials/back");
    EXPECT_EQ(back.typeName, "Material");
    EXPECT_EQ(back.attribute("outputs:surface")->connections,
              (std::vector<std::string>{scene + "/materials/back/usdpreviewsurface1.outputs:surface"}));
    EXPECT_EQ(back.attribute("outputs:mtlx:surface")->connections,
              (std::vector<std::string>{scene + "/materials/back/open_pbr_surface1.outputs:out"}));
    std::string map = corpusFile("usd-wg-assets/full_assets/StandardShaderBall/maps/wall_back.ACEScg.exr");
    EXPECT_EQ(value(*stage, scene + "/materials/back/mtlximage1", "inputs:file")->asString(), map);
    std::vector<AssetReference> assets = stage->assetReferences();
    auto wall = std::find_if(assets.begin(), assets.end(), [&](const AssetReference& a) {
        return a.primPath == scene + "/materials/back/mtlximage1";
    });
    ASSERT_NE(wall, assets.end());
    EXPECT_EQ(wall->authored, "../maps/wall_back.ACEScg.exr");
    EXPECT_EQ(wall->resolved, map);
    EXPECT_FALSE(wall->exists);
}

}  // namespace
}  // namespace fluence::usd
