// Curves and points inside prototypes (render/render_scene.h): placed by instances, they must be
// hit and shaded exactly as the same curves and points copied into world space, stored once, and
// their hits named by their instance.
#include <gtest/gtest.h>

#include <cmath>

#include "render/render_scene.h"

namespace fluence::render {
namespace {

// Rigid placements with a uniform scale (round tubes and spheres stay round), one mirrored, each
// with its scale of lengths.
struct Placement {
    Matrix4 toWorld;
    float scale = 1.0f;
};

std::vector<Placement> placements() {
    return {{Matrix4::translate({-3, 0, 0}) * Matrix4::rotateY(30) * Matrix4::scale({1.5, 1.5, 1.5}), 1.5f},
            {Matrix4::translate({0, 0.5, 0}) * Matrix4::rotateX(-45), 1.0f},
            {Matrix4::translate({3, 0, 0}) * Matrix4::scale({-1, 1, 1}), 1.0f}};
}

// A coloured cubic Bezier curve (two segments) and three spheres, in prototype space.
CurvesDesc hair() {
    CurvesDesc c;
    c.name = "/proto/hair";
    c.basis = CurveBasis::Bezier;
    for (int i = 0; i < 7; ++i) {
        const float s = float(i) / 6.0f;
        c.points.emplace_back(-1.0f + 2.0f * s, 0.6f * std::sin(3.0f * s), 0.3f * s);
        c.radii.push_back(0.08f + 0.05f * s);
        c.colors.emplace_back(s, 0.5f, 1.0f - s);
    }
    c.segments = {0, 3};
    return c;
}

PointsDesc particles() {
    PointsDesc p;
    p.name = "/proto/particles";
    for (int i = 0; i < 3; ++i) {
        p.positions.emplace_back(-0.8f + 0.8f * float(i), -0.8f, 0.2f * float(i));
        p.radii.push_back(0.2f + 0.05f * float(i));
        p.colors.emplace_back(0.2f * float(i), 0.7f, 0.1f);
    }
    return p;
}

std::pair<SceneDescription, SceneDescription> instancedAndCopied() {
    SceneDescription instanced, copied;
    instanced.prototypes.push_back({"/proto", {}, {hair()}, {particles()}});
    for (const Placement& placement : placements()) {
        const Matrix4& m = placement.toWorld;
        instanced.instances.push_back({0, m, "/instance" + std::to_string(instanced.instances.size())});
        CurvesDesc c = hair();
        for (Vec3f& p : c.points) p = Vec3f(m.transformPoint(Vec3d(p)));
        for (float& r : c.radii) r *= placement.scale;
        copied.curves.push_back(c);
        PointsDesc p = particles();
        for (Vec3f& x : p.positions) x = Vec3f(m.transformPoint(Vec3d(x)));
        for (float& r : p.radii) r *= placement.scale;
        copied.points.push_back(p);
    }
    return {instanced, copied};
}

TEST(InstancedCurvesAndPoints, InstancesAreHitAndShadedAsWorldCopies) {
    auto [instancedDesc, copiedDesc] = instancedAndCopied();
    RenderScene instanced(instancedDesc), copied(copiedDesc);
    EXPECT_EQ(instanced.stats().instances, 3u);
    EXPECT_EQ(instanced.stats().curves, 1u) << "the prototype's curves are stored once";
    EXPECT_EQ(instanced.stats().points, 3u) << "the prototype's points are stored once";
    EXPECT_EQ(copied.stats().curves, 3u);

    // A grid of parallel rays, tilted off the axes, over every placement.
    int curveHits = 0, pointHits = 0;
    for (int i = 0; i < 24000; ++i) {
        const Ray ray{Vec3f(-6.0f + 0.05f * float(i % 240), -2.5f + 0.05f * float(i / 240), 8.0f),
                      normalize(Vec3f(0.1f, 0.05f, -1.0f))};
        const std::optional<SurfaceHit> a = instanced.intersect(ray), b = copied.intersect(ray);
        ASSERT_EQ(a.has_value(), b.has_value()) << "ray " << i;
        if (!b) continue;
        (b->material.hair ? curveHits : pointHits) += 1;
        ASSERT_EQ(a->material.hair.has_value(), b->material.hair.has_value()) << "ray " << i;
        EXPECT_NEAR(a->t, b->t, 1e-3f * b->t) << "ray " << i;
        EXPECT_LT(length(a->point - b->point), 1e-3f * (1 + length(b->point))) << "ray " << i;
        EXPECT_GT(dot(a->geometricNormal, b->geometricNormal), 0.999f) << "ray " << i;
        EXPECT_GT(dot(a->shadingNormal, b->shadingNormal), 0.999f) << "ray " << i;
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(a->material.diffuse[k], b->material.diffuse[k], 1e-3f) << "ray " << i;
        if (b->material.hair) {
            EXPECT_GT(std::abs(dot(a->tangent, b->tangent)), 0.999f) << "ray " << i;
            EXPECT_NEAR(a->material.hair->offset, b->material.hair->offset, 2e-2f) << "ray " << i;
        }
        EXPECT_EQ(instanced.objectNames().name(a->objectName).rfind("/instance", 0), 0u) << "named by its instance";
        Vec3f away = a->geometricNormal;
        EXPECT_EQ(instanced.occluded(offsetRayOrigin(a->point, away), away, 100.0f),
                  copied.occluded(offsetRayOrigin(b->point, away), away, 100.0f))
            << "ray " << i;
    }
    EXPECT_GT(curveHits, 200) << "the rays must exercise the instanced curves";
    EXPECT_GT(pointHits, 200) << "the rays must exercise the instanced points";
}

}  // namespace
}  // namespace fluence::render
