// The light tree: its probabilities are a distribution, choose() follows them (chi-square over
// the lights), no light that can reach a point is ruled out, and the choice follows the point.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <stdexcept>
#include <vector>

#include "core/frame.h"
#include "core/random.h"
#include "core/sampling.h"
#include "render/light_tree.h"
#include "render/lights/cylinder_light.h"
#include "render/lights/disk_light.h"
#include "render/lights/distant_light.h"
#include "render/lights/dome_light.h"
#include "render/lights/line_light.h"
#include "render/lights/point_light.h"
#include "render/lights/rect_light.h"
#include "render/lights/sphere_light.h"
#include "render/lights/triangle_light.h"
#include "tests/support/chi2.h"

namespace fluence::render {
namespace {

// A cone of `angle` degrees and `softness`, unfocused, with no IES profile.
LightShapingDesc spotCone(float angle, float softness) {
    LightShapingDesc shaping;
    shaping.coneAngleDegrees = angle;
    shaping.coneSoftness = softness;
    return shaping;
}

const SceneBounds kScene{Vec3f(0.0f), 10.0f};

// A mix of every kind of light scattered in a 10-unit box, with random sizes, turns and powers,
// some shaped; and a sun and a dome.
std::vector<std::unique_ptr<Light>> mixedLights(int count, bool withInfinite = true) {
    std::vector<std::unique_ptr<Light>> lights;
    SampleStream rng(99, 0, 0);
    for (int i = 0; i < count; ++i) {
        LightDesc d;
        d.name = "/light" + std::to_string(i);
        d.transform = Matrix4::translate({10.0 * rng.next() - 5.0, 10.0 * rng.next() - 5.0, 10.0 * rng.next() - 5.0}) *
                      Matrix4::rotateX(360.0 * rng.next()) * Matrix4::rotateY(360.0 * rng.next());
        d.radiance = RGB(0.1f + 5.0f * rng.next());
        d.radius = 0.05f + 0.4f * rng.next();
        d.width = 0.1f + rng.next();
        d.height = 0.1f + rng.next();
        d.length = 0.2f + 2.0f * rng.next();
        if (i % 5 == 0) d.shaping = spotCone(20.0f + 60.0f * rng.next(), 0.3f);
        switch (i % 7) {
            case 0: lights.push_back(std::make_unique<RectLight>(d)); break;
            case 1: lights.push_back(std::make_unique<DiskLight>(d)); break;
            case 2: lights.push_back(std::make_unique<SphereLight>(d)); break;
            case 3: lights.push_back(std::make_unique<PointLight>(d)); break;
            case 4: lights.push_back(std::make_unique<CylinderLight>(d)); break;
            case 5: lights.push_back(std::make_unique<LineLight>(d)); break;
            default: {
                Vec3f a(d.transform.transformPoint({0, 0, 0}));
                lights.push_back(std::make_unique<TriangleLight>(d.name, a, a + Vec3f(0.5f, 0, 0),
                                                                 a + Vec3f(0, 0.4f, 0.2f), d.radiance));
            }
        }
    }
    if (withInfinite) {
        LightDesc sun;
        sun.type = LightType::Distant;
        sun.radiance = RGB(3.0f);
        lights.push_back(std::make_unique<DistantLight>(sun));
        LightDesc dome;
        dome.type = LightType::Dome;
        dome.radiance = RGB(0.2f);
        lights.push_back(std::make_unique<DomeLight>(dome));
    }
    return lights;
}

struct Query {
    Vec3f p, n;
};

std::vector<Query> queries(int count) {
    std::vector<Query> out;
    for (int i = 0; i < count; ++i) {
        SampleStream rng(7, 1, i);
        Vec3f p(12.0f * rng.next() - 6.0f, 12.0f * rng.next() - 6.0f, 12.0f * rng.next() - 6.0f);
        out.push_back({p, i % 4 == 3 ? Vec3f(0.0f) : sampleUniformSphere(rng.next2D())});
    }
    return out;
}

TEST(LightTree, ProbabilitiesSumToOneAndMatchChoose) {
    auto lights = mixedLights(300);
    LightTree tree(lights, kScene);
    EXPECT_EQ(tree.nodeCount(), 2u * 300 - 1);
    for (const Query& q : queries(40)) {
        double sum = 0.0;
        for (std::size_t i = 0; i < lights.size(); ++i) sum += tree.probability(q.p, q.n, int(i));
        EXPECT_NEAR(sum, 1.0, 1e-4);
        for (int k = 0; k < 50; ++k) {
            LightChoice c = tree.choose(q.p, q.n, SampleStream(5, 2, k).next());
            ASSERT_GE(c.light, 0);
            EXPECT_NEAR(c.probability, tree.probability(q.p, q.n, c.light), 1e-5f * c.probability);
        }
    }
}

// Pearson's chi-square of 1,000,000 choices against probability(), cells below 5 expected
// pooled, at two points.
TEST(LightTree, ChoicesFollowTheProbabilities) {
    auto lights = mixedLights(120);
    LightTree tree(lights, kScene);
    for (const Query& q : {Query{Vec3f(1.0f, -2.0f, 0.5f), normalize(Vec3f(0.2f, 1.0f, 0.1f))},
                           Query{Vec3f(-4.0f, 3.0f, 2.0f), Vec3f(0.0f)}}) {
        constexpr int kN = 1000000;
        std::vector<double> observed(lights.size(), 0.0);
        for (int k = 0; k < kN; ++k) {
            LightChoice c = tree.choose(q.p, q.n, SampleStream(13, 0, k).next());
            ASSERT_GE(c.light, 0);
            observed[c.light] += 1.0;
        }
        double chi2 = 0.0, pooledObserved = 0.0, pooledExpected = 0.0;
        int cells = 0;
        for (std::size_t i = 0; i < lights.size(); ++i) {
            double expected = kN * double(tree.probability(q.p, q.n, int(i)));
            if (expected < 5.0) {
                pooledObserved += observed[i];
                pooledExpected += expected;
                continue;
            }
            chi2 += (observed[i] - expected) * (observed[i] - expected) / expected;
            ++cells;
        }
        if (pooledExpected >= 5.0) {
            chi2 += (pooledObserved - pooledExpected) * (pooledObserved - pooledExpected) / pooledExpected;
            ++cells;
        }
        ASSERT_GT(cells, 20);
        double pValue = test::upperIncompleteGammaQ(0.5 * (cells - 1), 0.5 * chi2);
        EXPECT_GT(pValue, test::kChi2Alpha) << "chi2 = " << chi2 << " over " << cells << " cells";
    }
}

// Wherever a light's own sample brings light to the surface, the tree gives it a chance.
TEST(LightTree, NeverRulesOutALightThatReachesThePoint) {
    auto lights = mixedLights(150);
    LightTree tree(lights, kScene);
    int checked = 0;
    for (const Query& q : queries(60))
        for (std::size_t i = 0; i < lights.size(); ++i)
            for (int k = 0; k < 16; ++k) {
                auto s = lights[i]->sample(q.p, SampleStream(17, i, k).next2D());
                bool facing = lengthSquared(q.n) == 0.0f || dot(q.n, s ? s->wi : Vec3f()) > 0.0f;
                if (!s || isBlack(s->Li) || !(s->pdf > 0.0f) || !facing) continue;
                ++checked;
                ASSERT_GT(tree.probability(q.p, q.n, int(i)), 0.0f) << lights[i]->name() << " reaches the point";
                break;
            }
    EXPECT_GT(checked, 2000);
}

TEST(LightTree, FavoursTheLightsNearAndFacingThePoint) {
    // 100 equal point lights one unit apart along x, one unit above the floor.
    std::vector<std::unique_ptr<Light>> lights;
    for (int i = 0; i < 100; ++i) {
        LightDesc d;
        d.radius = 0.1f;
        d.transform = Matrix4::translate({double(i), 1.0, 0.0});
        lights.push_back(std::make_unique<PointLight>(d));
    }
    LightTree tree(lights, kScene);
    Vec3f p(0.0f, 0.0f, 0.0f), up(0.0f, 1.0f, 0.0f);
    EXPECT_GT(tree.probability(p, up, 0), 0.2f) << "power alone would give 0.01";
    EXPECT_LT(tree.probability(p, up, 99), 0.001f);
    // Far below, facing away from the row, no light can reach the point.
    Vec3f below(49.5f, -100.0f, 0.0f);
    EXPECT_EQ(tree.choose(below, -up, 0.5f).light, -1);
    EXPECT_EQ(tree.probability(below, -up, 0), 0.0f);
}

TEST(LightTree, ShapedLightsAreNotChosenOutsideTheirCone) {
    LightDesc d;
    d.radius = 0.1f;
    d.shaping = spotCone(30.0f, 0.0f);
    d.transform = Matrix4::translate({0, 2, 0}) * Matrix4::rotateX(-90);  // a spot pointing down -Y
    std::vector<std::unique_ptr<Light>> lights;
    lights.push_back(std::make_unique<PointLight>(d));
    LightTree tree(lights, kScene);
    EXPECT_FLOAT_EQ(tree.probability(Vec3f(0.3f, 0, 0), Vec3f(0, 1, 0), 0), 1.0f);  // 8.5 degrees off the axis
    EXPECT_EQ(tree.choose(Vec3f(3.0f, 0, 0), Vec3f(0, 1, 0), 0.3f).light, -1);      // 56 degrees off
}

// Beside a black sun, which weighs 0, a light takes the general walk, whose choice is that light
// with probability importance / importance = 1, or none where the importance is 0. Alone, it takes
// the one-light shortcut (plane tests instead of the importance), which must agree: at random
// points and normals, and at points and normals placed on either side of the emission and
// reception planes at distances from 2^-3 to 2^-24 of the bounding radius (in and out of the
// shortcut's slack), and just outside the bounding sphere.
TEST(LightTree, OneLightChoosesAsTheGeneralWalkDoes) {
    LightDesc blackSun;
    blackSun.type = LightType::Distant;
    blackSun.radiance = RGB(0.0f);
    LightDesc d;
    d.transform = Matrix4::translate({0.3, 1.5, -0.2}) * Matrix4::rotateX(70.0) * Matrix4::rotateY(25.0);
    d.width = 0.8f;
    d.height = 0.5f;
    d.radius = 0.3f;
    LightDesc shaped = d;
    shaped.shaping = spotCone(40.0f, 0.2f);
    std::vector<std::function<std::unique_ptr<Light>()>> kinds = {
        [&] { return std::make_unique<RectLight>(d); },
        [&] { return std::make_unique<DiskLight>(d); },
        [&] { return std::make_unique<RectLight>(shaped); },
        [&] { return std::make_unique<SphereLight>(d); },
        [&] { return std::make_unique<PointLight>(shaped); },
        [&] {
            return std::make_unique<TriangleLight>("/tri", Vec3f(0.2f, 1.0f, 0.0f), Vec3f(0.9f, 1.2f, 0.1f),
                                                   Vec3f(0.3f, 1.1f, 0.8f), RGB(2.0f));
        },
    };
    for (std::size_t kind = 0; kind < kinds.size(); ++kind) {
        std::vector<std::unique_ptr<Light>> alone, besideTheSun;
        alone.push_back(kinds[kind]());
        besideTheSun.push_back(kinds[kind]());
        besideTheSun.push_back(std::make_unique<DistantLight>(blackSun));
        LightTree one(alone, kScene), general(besideTheSun, kScene);
        ASSERT_EQ(one.nodeCount(), 1u);
        ASSERT_EQ(general.nodeCount(), 1u);
        const LightBounds b = *alone[0]->bounds();
        const Vec3f centre = (b.lo + b.hi) * 0.5f;
        const float radius = 0.5f * length(b.hi - b.lo);
        int chosen = 0, ruledOut = 0;
        for (int i = 0; i < 40000; ++i) {
            SampleStream rng(23, kind, i);
            const float e = (rng.next() < 0.5f ? -1.0f : 1.0f) * std::ldexp(1.0f, -3 - int(22.0f * rng.next()));
            Vec3f p(12.0f * rng.next() - 6.0f, 12.0f * rng.next() - 6.0f, 12.0f * rng.next() - 6.0f);
            Vec3f n = sampleUniformSphere(rng.next2D());
            const Frame axisFrame = Frame::fromNormal(b.axis);
            switch (i % 5) {
                case 0: break;
                case 1: n = Vec3f(0.0f); break;
                case 2:  // on the emission plane, dot(axis, p - centre) = -radius (1 + e)
                    p = centre + axisFrame.toWorld(
                                     Vec3f(5.0f * rng.next() - 2.5f, 5.0f * rng.next() - 2.5f, -radius * (1.0f + e)));
                    break;
                case 3: {  // n on the reception plane's edge, dot(n, p - centre) = radius (1 + e)
                    const Vec3f v = p - centre;
                    const float cosine = radius * (1.0f + e) / length(v);
                    if (cosine > 1.0f) break;
                    const Frame toV = Frame::fromNormal(normalize(v));
                    const float phi = 2.0f * kPi * rng.next();
                    const float sine = std::sqrt(1.0f - cosine * cosine);
                    n = toV.toWorld(Vec3f(sine * std::cos(phi), sine * std::sin(phi), cosine));
                    break;
                }
                default:  // just outside the bounding sphere
                    p = centre + sampleUniformSphere(rng.next2D()) * (radius * (1.0f + std::abs(e)));
            }
            const float u = rng.next();
            const LightChoice a = one.choose(p, n, u), g = general.choose(p, n, u);
            ASSERT_EQ(a.light, g.light) << "kind " << kind << " query " << i;
            ASSERT_EQ(a.probability, g.probability) << "kind " << kind << " query " << i;
            ASSERT_EQ(one.probability(p, n, 0), general.probability(p, n, 0)) << "kind " << kind << " query " << i;
            ++(a.light == 0 ? chosen : ruledOut);
        }
        // Both answers are given often (the sphere and the point light reach every point, so only
        // the normal rules them out).
        EXPECT_GT(chosen, 6000) << "kind " << kind;
        EXPECT_GT(ruledOut, 4000) << "kind " << kind;
        const Vec3f nan(std::numeric_limits<float>::quiet_NaN());
        EXPECT_EQ(one.choose(nan, Vec3f(0, 1, 0), 0.5f).light, -1);
        EXPECT_EQ(one.probability(nan, Vec3f(0, 1, 0), 0), 0.0f);
    }
}

TEST(LightTree, LightsAtInfinityAloneAreChosenByPower) {
    auto lights = mixedLights(0);
    LightTree tree(lights, kScene);
    EXPECT_EQ(tree.nodeCount(), 0u);
    float sun = lights[0]->power(kScene), dome = lights[1]->power(kScene);
    EXPECT_NEAR(tree.probability(Vec3f(1, 2, 3), Vec3f(0, 1, 0), 0), sun / (sun + dome), 1e-6f);
    EXPECT_EQ(tree.choose(Vec3f(1, 2, 3), Vec3f(0, 1, 0), 0.999f).light, 1);
}

TEST(LightTree, AChoiceMaskOfAnotherSizeIsRefused) {
    auto lights = mixedLights(3);
    EXPECT_THROW(LightTree(lights, kScene, std::vector<bool>(lights.size() - 1, true)), std::invalid_argument);
    EXPECT_THROW(LightTree(lights, kScene, std::vector<bool>(lights.size() + 1, true)), std::invalid_argument);
    EXPECT_NO_THROW(LightTree(lights, kScene, std::vector<bool>(lights.size(), true)));
}

TEST(LightTree, ManyLightsGiveAShallowTree) {
    auto lights = mixedLights(20000, false);
    LightTree tree(lights, kScene);
    EXPECT_EQ(tree.nodeCount(), 2u * 20000 - 1);
    EXPECT_LE(tree.depth(), 40) << "log2(20000) = 14.3";
}

}  // namespace
}  // namespace fluence::render
