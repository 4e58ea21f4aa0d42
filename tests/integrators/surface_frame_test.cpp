// What the surface integrators share (integrators/surface_frame.h, integrators/russian_roulette.h):
// the shading frame of a hit (its tangent, and which BSDFs see it flipped), the check that a
// direction leaves on the side its shading direction says, where rays leaving a hit start, Veach's
// adjoint shading-normal correction, and Russian roulette inside glass.
#include "integrators/russian_roulette.h"
#include "integrators/surface_frame.h"

#include <gtest/gtest.h>

namespace fluence::integrators {
namespace {

render::SurfaceHit tiltedHit() {
    render::SurfaceHit hit;
    hit.point = Vec3f(0.3f, -0.2f, 1.0f);
    hit.geometricNormal = Vec3f(0.0f, 0.0f, 1.0f);
    hit.shadingNormal = normalize(Vec3f(0.1f, 0.0f, 1.0f));
    hit.tangent = normalize(Vec3f(1.0f, 0.0f, -0.1f));  // perpendicular to the shading normal
    return hit;
}

void expectOrthonormal(const Frame& f) {
    EXPECT_NEAR(length(f.s), 1.0f, 1e-6f);
    EXPECT_NEAR(length(f.t), 1.0f, 1e-6f);
    EXPECT_NEAR(dot(f.s, f.t), 0.0f, 1e-6f);
    EXPECT_NEAR(dot(f.s, f.n), 0.0f, 1e-6f);
    EXPECT_NEAR(dot(f.t, f.n), 0.0f, 1e-6f);
    Vec3f c = cross(f.s, f.t);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(c[i], f.n[i], 1e-6f) << "right-handed";
}

TEST(ShadingFrame, FollowsTheTangentAndFlipsOnlyForTwoSidedBsdfs) {
    const render::SurfaceHit hit = tiltedHit();
    const Vec3f above(0.0f, 0.3f, 1.0f), below(0.0f, 0.3f, -1.0f);
    for (bool transmissive : {false, true})
        for (const Vec3f& wo : {normalize(above), normalize(below)}) {
            SCOPED_TRACE(testing::Message() << (transmissive ? "transmissive" : "two-sided") << ", wo.z " << wo.z);
            SurfaceFrame f = shadingFrame(hit, wo, transmissive);
            expectOrthonormal(f.frame);
            bool flipped = !transmissive && wo.z < 0.0f;
            EXPECT_EQ(f.frame.n, flipped ? -hit.shadingNormal : hit.shadingNormal);
            EXPECT_EQ(f.geometricNormal, flipped ? -hit.geometricNormal : hit.geometricNormal);
            for (int i = 0; i < 3; ++i) EXPECT_NEAR(f.frame.s[i], hit.tangent[i], 1e-6f) << "x along the tangent";
            EXPECT_EQ(f.frame.toLocal(wo).z > 0.0f, transmissive ? wo.z > 0.0f : true);
        }
    // A tangent not quite perpendicular is projected; none at all gives the normal's own frame.
    Frame projected = Frame::fromNormalAndTangent(hit.shadingNormal, Vec3f(1.0f, 0.0f, 0.0f));
    expectOrthonormal(projected);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(projected.s[i], hit.tangent[i], 1e-6f);
    render::SurfaceHit plain = hit;
    plain.tangent = Vec3f(0.0f);
    Frame fallback = shadingFrame(plain, above, false).frame, reference = Frame::fromNormal(hit.shadingNormal);
    EXPECT_EQ(fallback.s, reference.s);
    EXPECT_EQ(fallback.t, reference.t);
}

TEST(ShadingFrame, DirectionsMustLeaveOnTheSideTheirShadingSays) {
    const Vec3f ng(0.0f, 0.0f, 1.0f), wo = normalize(Vec3f(0.2f, 0.0f, 1.0f));
    const Vec3f up = normalize(Vec3f(-0.3f, 0.1f, 1.0f)), down = normalize(Vec3f(-0.3f, 0.1f, -1.0f));
    EXPECT_TRUE(sidesAgree(wo, up, ng, 0.9f, 0.8f)) << "reflection above";
    EXPECT_TRUE(sidesAgree(wo, down, ng, 0.9f, -0.8f)) << "transmission through";
    EXPECT_FALSE(sidesAgree(wo, down, ng, 0.9f, 0.1f)) << "a reflection the geometry sends through: a leak";
    EXPECT_FALSE(sidesAgree(wo, up, ng, 0.9f, -0.1f)) << "a transmission the geometry turns back";
    EXPECT_FALSE(sidesAgree(wo, Vec3f(1.0f, 0.0f, 0.0f), ng, 0.9f, 0.1f)) << "along the surface";
    EXPECT_TRUE(sidesAgree(-wo, -up, ng, -0.9f, -0.8f)) << "the same seen from below";
}

TEST(ShadingFrame, RaysStartOnTheSideTheyLeaveBy) {
    const Vec3f p(0.3f, -0.2f, 1.0f), ng(0.0f, 0.0f, 1.0f);
    EXPECT_GT(spawnOrigin(p, ng, Vec3f(0.0f, 0.6f, 0.8f)).z, p.z);
    EXPECT_LT(spawnOrigin(p, ng, Vec3f(0.0f, 0.6f, -0.8f)).z, p.z);
    EXPECT_LT(spawnOrigin(p, -ng, Vec3f(0.0f, 0.6f, -0.8f)).z, p.z) << "whichever way the normal points";
}

// Veach's correction is |wo.ns| |wi.ng| / |wo.ng|: |wi.n| where the shading normal is the geometric
// one (no correction), and, with a tilted shading normal, the ratio of the cosines it changes.
TEST(ShadingFrame, AdjointCosineIsVeachsCorrection) {
    const Vec3f ng(0.0f, 0.0f, 1.0f), ns = normalize(Vec3f(0.3f, 0.0f, 1.0f));
    const Vec3f wo = normalize(Vec3f(0.5f, 0.2f, 0.8f)), wi = normalize(Vec3f(-0.4f, 0.1f, 0.6f));
    EXPECT_FLOAT_EQ(adjointShadingCosine(wo, wi, ng, ng), wi.z);
    EXPECT_FLOAT_EQ(adjointShadingCosine(wo, wi, ns, ng), dot(wo, ns) * wi.z / wo.z);
    EXPECT_EQ(adjointShadingCosine(Vec3f(1.0f, 0.0f, 0.0f), wi, ns, ng), 0.0f) << "wo grazing the geometric surface";
}

TEST(RussianRoulette, RadianceScaledByRefractionIsNoReasonToEndAPath) {
    // Inside glass of index 1.5 the radiance throughput is 1 / 2.25 while etaScale is 2.25: the
    // survival probability is that of a throughput of 1 (0.95), and survivors are reweighted by it.
    const int kPaths = 20'000;
    int survived = 0;
    for (int n = 0; n < kPaths; ++n) {
        SampleStream rng(11, 0, n);
        RGB throughput(1.0f / 2.25f);
        if (continuePath(throughput, 2.25f, 5, rng)) {
            ++survived;
            EXPECT_NEAR(throughput.x, 1.0f / (2.25f * 0.95f), 1e-6f);
        }
    }
    // Binomial, at 5 standard errors: sqrt(0.95 * 0.05 / 20000) = 0.0015.
    EXPECT_NEAR(double(survived) / kPaths, 0.95, 5 * 0.0015);
    RGB early(1e-3f);
    SampleStream rng(11, 0, 0);
    EXPECT_TRUE(continuePath(early, 1.0f, 0, rng)) << "no roulette in the first bounces";
}

TEST(RussianRoulette, SurvivalIsTheSquareRootOfTheThroughputFromTheFifthVertex) {
    // A throughput of 0.25 survives with probability sqrt(0.25) = 0.5 and is reweighted to 0.5.
    const int kPaths = 20'000;
    int survived = 0;
    for (int n = 0; n < kPaths; ++n) {
        SampleStream rng(12, 0, n);
        RGB throughput(0.25f, 0.1f, 0.05f);
        if (continuePath(throughput, 1.0f, 3, rng)) {
            ++survived;
            EXPECT_NEAR(throughput.x, 0.5f, 1e-6f);
        }
    }
    // Binomial, at 5 standard errors: sqrt(0.5 * 0.5 / 20000) = 0.0035.
    EXPECT_NEAR(double(survived) / kPaths, 0.5, 5 * 0.0035);
    for (int depth = 0; depth < 3; ++depth) {
        RGB dim(1e-3f);
        SampleStream rng(12, 0, 0);
        EXPECT_TRUE(continuePath(dim, 1.0f, depth, rng)) << "the first four vertices are always shaded: " << depth;
        EXPECT_EQ(dim.x, 1e-3f);
    }
}

}  // namespace
}  // namespace fluence::integrators
