// The hit's BSDF made with the scene (render/material_tables.h, SurfaceHit::bsdf): a hit whose
// material parameters are the authored ones carries its material's BSDF, which gives the values
// materialBsdf makes at the hit, bit for bit; a hit whose parameters a vertex colour or a binding
// drives carries none. And RenderScene::trace finds the nearest triangle, which shade shades where the
// ray met it (a guided walk's entry step shades its far side only when it reaches it,
// integrators/path_tracer.cpp; intersect is shade after trace).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "render/bsdf_arena.h"
#include "render/material_bsdf.h"
#include "render/render_scene.h"
#include "tests/support/scenes.h"

namespace fluence::render {
namespace {

// The subsurface peer's skin (bench/peer_scenes/cycles_sss.usda): subsurface under a rough specular layer.
MaterialDesc skin() {
    MaterialDesc m;
    m.subsurface = 1.0f;
    m.subsurfaceColor = RGB(0.8f, 0.45f, 0.35f);
    m.specular = 0.5f;
    m.roughness = 0.35f;
    m.ior = 1.4f;
    return m;
}

// A coated metal with sheen: other layers than the skin's.
MaterialDesc coatedMetal() {
    MaterialDesc m;
    m.diffuse = RGB(0.9f, 0.6f, 0.3f);
    m.metallic = 0.7f;
    m.roughness = 0.2f;
    m.coat = 0.6f;
    m.sheen = 0.4f;
    return m;
}

// Two unit spheres, at x = -2 and x = +2, of materials `left` and `right`.
SceneDescription twoSpheres(int left, int right) {
    SceneDescription scene;
    scene.materials = {skin(), coatedMetal()};
    MeshDesc a = test::sphereMesh(1.0f, 24, 12, left), b = test::sphereMesh(1.0f, 24, 12, right);
    for (Vec3f& p : a.positions) p.x -= 2.0f;
    for (Vec3f& p : b.positions) p.x += 2.0f;
    scene.meshes = {a, b};
    return scene;
}

// The hit of a ray from in front (-y) of the sphere centred at x, slightly off its middle.
std::optional<SurfaceHit> hitOn(const RenderScene& scene, float x) {
    return scene.intersect(Ray{Vec3f(x + 0.3f, -5.0f, 0.2f), Vec3f(0.0f, 1.0f, 0.0f)});
}

// Directions on both sides of the surface, in the local shading frame.
std::vector<Vec3f> directions() {
    std::vector<Vec3f> out;
    for (float z : {0.9f, 0.4f, 0.05f, -0.3f, -0.8f})
        for (float phi : {0.3f, 2.1f, 4.4f}) {
            const float r = std::sqrt(1.0f - z * z);
            out.emplace_back(r * std::cos(phi), r * std::sin(phi), z);
        }
    return out;
}

// `kept` and `made` give the same values, bit for bit, for every pair of directions and samples.
void expectSameBsdf(const Bsdf& kept, const Bsdf& made) {
    ASSERT_EQ(kept.flags(), made.flags());
    for (const Vec3f& wo : directions()) {
        for (const Vec3f& wi : directions()) {
            const RGB fKept = kept.f(wo, wi), fMade = made.f(wo, wi);
            for (int c = 0; c < 3; ++c) EXPECT_EQ(fKept[c], fMade[c]);
            EXPECT_EQ(kept.pdf(wo, wi), made.pdf(wo, wi));
        }
        for (float uLobe : {0.05f, 0.5f, 0.95f})
            for (const Vec2f u : {Vec2f(0.1f, 0.7f), Vec2f(0.6f, 0.2f), Vec2f(0.93f, 0.45f)}) {
                const std::optional<BsdfSample> a = kept.sample(wo, uLobe, u), b = made.sample(wo, uLobe, u);
                ASSERT_EQ(a.has_value(), b.has_value());
                if (!a) continue;
                for (int c = 0; c < 3; ++c) {
                    EXPECT_EQ(a->f[c], b->f[c]);
                    EXPECT_EQ(a->wi[c], b->wi[c]);
                }
                EXPECT_EQ(a->pdf, b->pdf);
                EXPECT_EQ(a->specular, b->specular);
                EXPECT_EQ(a->eta, b->eta);
            }
    }
}

TEST(SceneMaterialBsdf, AHitOfAuthoredParametersCarriesItsMaterialsBsdfBitForBit) {
    for (const auto& [left, right] : {std::pair(0, 1), std::pair(1, 0)}) {
        const RenderScene scene(twoSpheres(left, right));
        for (const float x : {-2.0f, 2.0f}) {
            const std::optional<SurfaceHit> hit = hitOn(scene, x);
            ASSERT_TRUE(hit);
            ASSERT_NE(hit->bsdf, nullptr) << "no binding, no vertex colour: the scene's BSDF";
            BsdfArena arena;
            expectSameBsdf(*hit->bsdf, materialBsdf(hit->material, arena));
        }
    }
}

TEST(SceneMaterialBsdf, AHitWhoseParametersAVertexColourOrABindingDrivesCarriesNone) {
    SceneDescription scene = twoSpheres(0, 1);
    MeshDesc& coloured = scene.meshes[0];
    coloured.cornerColors.assign(coloured.indices.size(), RGB(0.2f, 0.7f, 0.4f));
    InputBinding tint;  // the diffuse colour from a primvar the mesh lacks: its fallback
    tint.input = MaterialInput::Diffuse;
    tint.primvar = "tint";
    tint.primvarFallback[0] = 0.3f;
    scene.materials[1].bindings.push_back(tint);
    const RenderScene rendered(scene);
    for (const float x : {-2.0f, 2.0f}) {
        const std::optional<SurfaceHit> hit = hitOn(rendered, x);
        ASSERT_TRUE(hit);
        EXPECT_EQ(hit->bsdf, nullptr) << "the sphere at x = " << x << " has per-hit parameters";
    }
}

TEST(SceneMaterialBsdf, TraceFindsTheNearestTriangleAndShadeThePointOnIt) {
    const SceneDescription description = twoSpheres(0, 1);
    const RenderScene scene(description);
    const Ray missing{Vec3f(0.0f, -5.0f, 3.0f), Vec3f(0.0f, 1.0f, 0.0f)};
    const TracedHit none = scene.trace(missing);
    EXPECT_FALSE(none.met());
    EXPECT_EQ(none.t, std::numeric_limits<float>::infinity());
    EXPECT_FALSE(scene.shade(none, missing));
    const MeshDesc& ball = description.meshes[1];
    for (std::size_t t = 0; t < ball.indices.size() / 3; t += 7) {
        const Vec3f p0 = ball.positions[ball.indices[3 * t]], p1 = ball.positions[ball.indices[3 * t + 1]],
                    p2 = ball.positions[ball.indices[3 * t + 2]];
        const Vec3f unit = normalize(cross(p1 - p0, p2 - p0));
        const Vec3f aim = p0 * 0.6f + p1 * 0.3f + p2 * 0.1f;  // barycentrics (0.3, 0.1): u and v apart
        const Ray ray{aim + unit * 2.0f, -unit};              // from outside, 2 away
        const TracedHit traced = scene.trace(ray);
        ASSERT_TRUE(traced.met()) << "triangle " << t;
        EXPECT_FALSE(traced.lightShape);
        EXPECT_EQ(traced.primID, t);
        EXPECT_NEAR(traced.t, 2.0f, 1e-5f);
        const std::optional<SurfaceHit> shaded = scene.shade(traced, ray);
        ASSERT_TRUE(shaded);
        EXPECT_EQ(shaded->t, traced.t);
        EXPECT_EQ(shaded->triangle, t);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(shaded->point[c], aim[c], 1e-5f) << "triangle " << t;
    }
}

}  // namespace
}  // namespace fluence::render
