// Embree instancing in the render scene: a prototype placed by instances must be hit, shaded and
// lit exactly as the same geometry copied into world space, while being stored once.
#include <gtest/gtest.h>

#include <cmath>

#include "core/random.h"
#include "render/mesh_transform.h"
#include "render/render_scene.h"
#include "tests/support/scenes.h"

namespace fluence::render {
namespace {

// Placements that rotate, scale non-uniformly, and mirror.
std::vector<Matrix4> placements() {
    return {Matrix4::translate({-3, 0, 0}) * Matrix4::rotateY(30) * Matrix4::scale({1, 2, 1}),
            Matrix4::translate({0, 0.5, 0}) * Matrix4::rotateX(-45),
            Matrix4::translate({3, 0, 0}) * Matrix4::scale({-1, 1, 1.5})};
}

// The same geometry twice: as one prototype with instances, and copied into world space.
std::pair<SceneDescription, SceneDescription> instancedAndCopied(int material) {
    MeshDesc ball = test::sphereMesh(0.75f, 24, 12, material);
    ball.cornerColors.assign(ball.indices.size(), RGB(0.2f, 0.4f, 0.6f));
    SceneDescription instanced, copied;
    MaterialDesc glow = test::diffuseMaterial("glow", RGB(0.5f), RGB(material >= 0 ? 2.0f : 0.0f));
    instanced.materials = copied.materials = {glow};
    instanced.prototypes.push_back({"/proto", {ball}});
    for (const Matrix4& m : placements()) {
        instanced.instances.push_back({0, m, ""});
        copied.meshes.push_back(transformMesh(ball, m));
    }
    return {instanced, copied};
}

TEST(Instancing, InstancesAreHitAndShadedAsWorldCopies) {
    auto [instancedDesc, copiedDesc] = instancedAndCopied(-1);
    RenderScene instanced(instancedDesc), copied(copiedDesc);
    EXPECT_EQ(instanced.stats().instances, 3u);
    EXPECT_EQ(instanced.stats().triangles * 3, copied.stats().triangles) << "the prototype is stored once";
    EXPECT_EQ(instanced.stats().instancedTriangles, copied.stats().triangles);

    SampleStream random(0x5eed, 0, 0);
    int hits = 0;
    for (int i = 0; i < 4000; ++i) {
        // Rays from a box around the scene towards random points near the placements.
        Vec3f origin(random.next() * 12 - 6, random.next() * 8 - 4, 6.0f + random.next());
        Vec3f target(random.next() * 8 - 4, random.next() * 3 - 1.5f, random.next() * 2 - 1);
        Ray ray{origin, normalize(target - origin)};
        auto a = instanced.intersect(ray);
        auto b = copied.intersect(ray);
        ASSERT_EQ(a.has_value(), b.has_value()) << "ray " << i;
        if (!a) continue;
        ++hits;
        EXPECT_NEAR(a->t, b->t, 1e-4f * b->t);
        EXPECT_LT(length(a->point - b->point), 1e-4f * (1 + length(b->point)));
        EXPECT_GT(dot(a->geometricNormal, b->geometricNormal), 0.9999f) << "ray " << i;
        EXPECT_GT(dot(a->shadingNormal, b->shadingNormal), 0.9999f) << "ray " << i;
        EXPECT_NEAR(a->material.diffuse.y, b->material.diffuse.y, 1e-6f);
        Vec3f away = a->geometricNormal;
        EXPECT_EQ(instanced.occluded(offsetRayOrigin(a->point, away), away, 100.0f),
                  copied.occluded(offsetRayOrigin(b->point, away), away, 100.0f));
    }
    EXPECT_GT(hits, 500) << "the rays must exercise the instances";
}

TEST(Instancing, EmissivePrototypesBecomeLightsPerInstance) {
    auto [instancedDesc, copiedDesc] = instancedAndCopied(0);
    RenderScene instanced(instancedDesc), copied(copiedDesc);
    EXPECT_EQ(instanced.lightCount(), copied.lightCount());
    EXPECT_EQ(instanced.stats().emissiveTriangles, copied.stats().emissiveTriangles);
    ASSERT_EQ(instanced.lightSelection().size(), copied.lightSelection().size());
    for (std::size_t i = 0; i < copied.lightSelection().size(); ++i)
        EXPECT_FLOAT_EQ(instanced.lightSelection().pmf(i), copied.lightSelection().pmf(i));
}

TEST(Instancing, AnInstanceOfAMissingPrototypeIsRejected) {
    SceneDescription scene;
    scene.instances.push_back({2, Matrix4::identity(), ""});
    EXPECT_THROW(RenderScene{scene}, std::invalid_argument);
}

}  // namespace
}  // namespace fluence::render
