// The BSDF interface's plumbing: the per-hit arena, and the Lambertian's exact properties.
#include "render/bsdf.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "core/random.h"
#include "render/bsdf_arena.h"
#include "render/bsdfs/coated.h"
#include "render/bsdfs/lambertian.h"
#include "render/bsdfs/oren_nayar.h"

namespace fluence::render {
namespace {

TEST(BsdfArena, BuildsLayeredBsdfsAndIsReusableAfterReset) {
    BsdfArena arena;
    for (int hit = 0; hit < 3; ++hit) {
        arena.reset();
        const Bsdf& base = arena.make<LambertianBsdf>(RGB(0.5f));
        const Bsdf& coated = arena.make<CoatedBsdf>(base, 1.5f, 0.2f);
        EXPECT_EQ(coated.flags(), unsigned(kBsdfReflection | kBsdfDiffuse | kBsdfGlossy));
        Vec3f wo(0, 0, 1), wi = normalize(Vec3f(1, 0, 1));
        EXPECT_GT(coated.f(wo, wi).x, 0.0f);
    }
}

TEST(BsdfArena, ThrowsWhenFull) {
    BsdfArena arena;
    auto fill = [&] {
        for (std::size_t i = 0; i <= BsdfArena::kCapacity / sizeof(LambertianBsdf); ++i)
            arena.make<LambertianBsdf>(RGB(0.5f));
    };
    EXPECT_THROW(fill(), std::length_error);
    arena.reset();
    EXPECT_NO_THROW(arena.make<LambertianBsdf>(RGB(0.5f)));
}

TEST(LambertianBsdf, EverySampleWeighsExactlyTheAlbedo) {
    // Cosine sampling makes f |cos| / pdf the albedo for every sample, on both sides.
    LambertianBsdf bsdf(RGB(1.0f, 0.5f, 0.25f));
    for (const Vec3f& wo : {normalize(Vec3f(0.2f, 0.3f, 0.9f)), normalize(Vec3f(0.2f, 0.3f, -0.9f))})
        for (int n = 0; n < 100; ++n) {
            auto s = bsdf.sample(wo, 0.5f, SampleStream(2, 0, n).next2D());
            ASSERT_TRUE(s);
            EXPECT_GT(s->wi.z * wo.z, 0.0f) << "reflection stays on the side of wo";
            RGB weight = s->f * (std::abs(s->wi.z) / s->pdf);
            EXPECT_NEAR(weight.x, 1.0f, 1e-6f);
            EXPECT_NEAR(weight.y, 0.5f, 1e-6f);
            EXPECT_NEAR(weight.z, 0.25f, 1e-6f);
        }
}

}  // namespace
}  // namespace fluence::render

namespace fluence::render {
namespace {

TEST(OrenNayar, ZeroSigmaIsLambertianAndRoughnessBackScatters) {
    const RGB albedo(0.6f);
    OrenNayarBsdf smooth(albedo, 0.0f), rough(albedo, 0.5f);
    LambertianBsdf lambert(albedo);
    const Vec3f wo = normalize(Vec3f(0.6f, 0.0f, 0.8f));
    for (const Vec3f& wi : {normalize(Vec3f(0.5f, 0.2f, 0.7f)), normalize(Vec3f(-0.7f, 0.1f, 0.3f)), Vec3f(0, 0, 1)})
        EXPECT_FLOAT_EQ(smooth.f(wo, wi).x, lambert.f(wo, wi).x);
    // A rough surface sends more light back towards the light (wi == wo) than on to the mirror
    // direction; a Lambertian one sends the same.
    const Vec3f mirror(-wo.x, -wo.y, wo.z);
    EXPECT_GT(rough.f(wo, wo).x, 1.1f * rough.f(wo, mirror).x);
    EXPECT_FLOAT_EQ(smooth.f(wo, wo).x, smooth.f(wo, mirror).x);
}

}  // namespace
}  // namespace fluence::render
