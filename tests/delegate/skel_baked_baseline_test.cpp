// UsdSkel against OpenUSD itself: the test scenes of testUsdSkelBakeSkinning (linear blend, dual
// quaternion, blend shapes with in-betweens and normal offsets) and the baselines
// UsdSkelBakeSkinning wrote for them (tests/delegate/data/usdskel/README.md). At every baked frame,
// each skinned Mesh's and implicit gprim's world-space points, and the direction of its normals, equal the baked
// mesh's (whose SkelRoot the bake turned into an Xform, so it renders as it is).
#include <gtest/gtest.h>

#include "tests/delegate/delegate_test_support.h"

namespace fluence::delegate {
namespace {

const std::string kData = FLUENCE_SOURCE_DIR "/tests/delegate/data/usdskel/";

render::SceneDescription describeAt(const std::string& file, double time, std::vector<std::string>& warnings) {
    std::unique_ptr<usd::Stage> stage = usd::Stage::open(kData + file);
    DelegateOptions options;
    options.time = time;
    options.convertColor = [](const RGB& c, const std::string&) { return c; };
    options.warn = [&warnings](const std::string& path, const std::string& message) {
        warnings.push_back(path + ": " + message);
    };
    return populateScene(*stage, options).scene;
}

// Compares the Meshes of `skinned` with those of `baked` over frames first..last.
void expectBakedPose(const std::string& skinned, const std::string& baked, int first, int last, std::size_t meshes) {
    for (int frame = first; frame <= last; ++frame) {
        std::vector<std::string> warnings;
        const render::SceneDescription ours = describeAt(skinned, frame, warnings);
        const render::SceneDescription theirs = describeAt(baked, frame, warnings);
        for (const std::string& w : warnings)
            EXPECT_TRUE(w.starts_with("/: ") || w.find("not supported yet") != std::string::npos) << w;
        std::size_t compared = 0;
        for (const render::MeshDesc& reference : theirs.meshes) {
            const render::MeshDesc* mesh = nullptr;
            for (const render::MeshDesc& m : ours.meshes) mesh = m.name == reference.name ? &m : mesh;
            if (!mesh) continue;
            ++compared;
            SCOPED_TRACE(skinned + " " + reference.name + " at frame " + std::to_string(frame));
            ASSERT_EQ(mesh->positions.size(), reference.positions.size());
            double worst = 0.0;
            for (std::size_t i = 0; i < mesh->positions.size(); ++i)
                worst = std::max(worst, length(Vec3d(mesh->positions[i]) - Vec3d(reference.positions[i])));
            EXPECT_LT(worst, 2e-5) << "largest distance of a point from the baked one";
            ASSERT_EQ(mesh->cornerNormals.size(), reference.cornerNormals.size());
            double worstNormal = 0.0;
            for (std::size_t i = 0; i < mesh->cornerNormals.size(); ++i)
                worstNormal =
                    std::max(worstNormal, length(Vec3d(mesh->cornerNormals[i]) - Vec3d(reference.cornerNormals[i])));
            EXPECT_LT(worstNormal, 1e-4) << "largest difference of a unit normal from the baked one";
        }
        EXPECT_EQ(compared, meshes) << "frame " << frame;
    }
}

TEST(SkelBakedBaseline, LinearBlendSkinningMatchesUsdSkelBakeSkinning) {
    expectBakedPose("lbs.usda", "lbs.bakedInterval.usda", 1, 10, 6);  // 3 meshes, a sphere, a cube, a cylinder
}

TEST(SkelBakedBaseline, DualQuaternionSkinningMatchesUsdSkelBakeSkinning) {
    expectBakedPose("dqs.usda", "dqs.bakedInterval.usda", 1, 10, 6);
}

TEST(SkelBakedBaseline, BlendShapesWithInBetweensAndNormalOffsetsMatchUsdSkelBakeSkinning) {
    expectBakedPose("blendshapesWithNormals.usda", "blendshapesWithNormals.baked.usda", 1, 10, 1);
}

}  // namespace
}  // namespace fluence::delegate
