// RenderScene::shadeMesh's geometric normal: a world mesh that does not move stores its triangles'
// unit normals when the scene is built (Mesh::unitNormals), a moving one computes them per hit.
// Either way a hit carries the unit normal of the triangle it met, normalize(cross(p1 - p0, p2 - p0)),
// bit for bit, so the stored table changes no image.
#include <gtest/gtest.h>

#include "render/render_scene.h"
#include "tests/support/scenes.h"

namespace fluence::render {
namespace {

TEST(MeshHitNormal, EveryTriangleHitCarriesItsOwnUnitNormalBitForBit) {
    const MeshDesc ball = test::sphereMesh(1.0f, 16, 9, -1);
    MeshDesc moving = ball;  // the same triangles, as a mesh with deformation blur (held still)
    moving.motionPositions = {ball.positions, ball.positions};
    SceneDescription stillScene, movingScene;
    stillScene.meshes = {ball};
    movingScene.meshes = {moving};
    const RenderScene still(stillScene), moved(movingScene);

    const std::size_t triangles = ball.indices.size() / 3;
    for (std::size_t t = 0; t < triangles; ++t) {
        const Vec3f p0 = ball.positions[ball.indices[3 * t]], p1 = ball.positions[ball.indices[3 * t + 1]],
                    p2 = ball.positions[ball.indices[3 * t + 2]];
        const Vec3f unit = normalize(cross(p1 - p0, p2 - p0));
        const Vec3f centroid = (p0 + p1 + p2) / 3.0f;
        const Ray ray{centroid + unit * 2.0f, -unit};  // towards the triangle's middle, from outside
        const std::optional<SurfaceHit> a = still.intersect(ray), b = moved.intersect(ray);
        ASSERT_TRUE(a && b) << "triangle " << t;
        ASSERT_EQ(a->triangle, t);
        ASSERT_EQ(b->triangle, t);
        for (int c = 0; c < 3; ++c) {
            EXPECT_EQ(a->geometricNormal[c], unit[c]) << "triangle " << t << " component " << c;
            EXPECT_EQ(b->geometricNormal[c], unit[c]) << "triangle " << t << " component " << c;
        }
    }
}

}  // namespace
}  // namespace fluence::render
