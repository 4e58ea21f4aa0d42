// UsdLux conformance: for each light type and attribute, the irradiance a light authored in USD
// delivers at a point, against the value the UsdLux specification (with the clarifications of
// OpenUSD PR 3182, which hdEmbree implements) gives, derived here from its formulas and the
// geometry alone. Each light goes the whole way: USDA -> delegate -> render::makeLight ->
// sample(). Delta lights (points, angle-0 distant lights) are exact; area lights are estimated
// from 100000 of their own samples, to five standard errors. docs/USDLUX.md tables the rules.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>

#include "core/random.h"
#include "core/sampling.h"
#include "render/lights/light_registry.h"
#include "tests/delegate/delegate_test_support.h"
#include "tests/support/statistics.h"

namespace fluence::delegate {
namespace {

using testing::populate;

constexpr double kPiD = 3.14159265358979323846;
constexpr double kDeg = kPiD / 180.0;

// The scene's one light, made by the render core.
std::unique_ptr<render::Light> lightOf(const std::string& usda) {
    auto p = populate(usda);
    if (p.result.scene.lights.size() != 1) throw std::runtime_error("expected one light");
    return render::makeLight(p.result.scene.lights[0]);
}

// A light prim of `type` 2 units above the origin facing down (its -Z along world -Y), with
// `inputs` (USDA lines) and a scale.
std::string downward(const std::string& type, const std::string& inputs, const std::string& scale = "(1, 1, 1)") {
    return "def " + type + " \"L\"\n{\n" + inputs +
           "\n    double3 xformOp:translate = (0, 2, 0)\n    float3 xformOp:rotateXYZ = (-90, 0, 0)\n"
           "    float3 xformOp:scale = " +
           scale +
           "\n    uniform token[] xformOpOrder = [\"xformOp:translate\", \"xformOp:rotateXYZ\", "
           "\"xformOp:scale\"]\n}\n";
}

// Irradiance at p (normal n) per channel, from the light's own samples.
struct Measured {
    RGB mean;
    double error = 0.0;  // the largest channel's standard error
};
Measured irradiance(const render::Light& light, const Vec3f& p, const Vec3f& n, int count = 100000) {
    test::MeanEstimate e[3];
    for (int i = 0; i < count; ++i) {
        auto s = light.sample(p, SampleStream(5, 0, std::uint64_t(i)).next2D());
        for (int c = 0; c < 3; ++c)
            e[c].add(s && s->pdf > 0.0f ? double(s->Li[c]) * std::max(0.0f, dot(n, s->wi)) / s->pdf : 0.0);
    }
    Measured m{RGB(float(e[0].mean()), float(e[1].mean()), float(e[2].mean()))};
    for (auto& c : e) m.error = std::max(m.error, c.standardError());
    return m;
}

void expectIrradiance(const std::string& usda, const Vec3f& p, const Vec3f& n, const RGB& expected) {
    Measured m = irradiance(*lightOf(usda), p, n);
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(m.mean[c], expected[c], 5.0 * m.error + 1e-4 * std::abs(expected[c]) + 1e-7)
            << "channel " << c << "\n"
            << usda;
}

const Vec3f kOrigin(0.0f), kUp(0.0f, 1.0f, 0.0f);

// intensity x 2^exposure x color: UsdLux's L (nits).
TEST(UsdLuxConformance, RectIntensityExposureColorAndNormalize) {
    // A point on the axis of a rectangle of half-sizes a, b at height h: the form factor of the
    // four corner rectangles, E = 2 L [X/sqrt(1+X^2) atan(Y/sqrt(1+X^2)) + (X <-> Y)], X = a/h, Y = b/h.
    auto onAxis = [](double a, double b, double h) {
        double x = a / h, y = b / h;
        return 2.0 * (x / std::sqrt(1 + x * x) * std::atan(y / std::sqrt(1 + x * x)) +
                      y / std::sqrt(1 + y * y) * std::atan(x / std::sqrt(1 + y * y)));
    };
    const std::string lit =
        "    float inputs:width = 2\n    float inputs:height = 1\n    float inputs:intensity = 3\n"
        "    float inputs:exposure = 1\n    color3f inputs:color = (0.5, 1, 0.25)";
    RGB L = RGB(0.5f, 1.0f, 0.25f) * 6.0f;
    expectIrradiance(downward("RectLight", lit), kOrigin, kUp, L * float(onAxis(1.0, 0.5, 2.0)));
    // normalize divides by the world-space area: scaled 2x along X, 4 x 1.
    expectIrradiance(downward("RectLight", lit + "\n    bool inputs:normalize = 1", "(2, 1, 1)"), kOrigin, kUp,
                     L / 4.0f * float(onAxis(2.0, 0.5, 2.0)));
}

TEST(UsdLuxConformance, DiskOnItsAxisAndNormalize) {
    // E = pi L R^2 / (R^2 + h^2) on the axis; normalized, L / (pi R^2).
    const std::string lit = "    float inputs:radius = 0.8\n    float inputs:intensity = 2.5";
    expectIrradiance(downward("DiskLight", lit), kOrigin, kUp, RGB(float(2.5 * kPiD * 0.64 / (0.64 + 4.0))));
    expectIrradiance(downward("DiskLight", lit + "\n    bool inputs:normalize = 1", "(1.5, 1.5, 1)"), kOrigin, kUp,
                     RGB(float(2.5 / (kPiD * 1.44) * kPiD * 1.44 / (1.44 + 4.0))));
}

TEST(UsdLuxConformance, SphereTreatAsPointAndNormalize) {
    // A sphere of radiance L and radius r seen from distance d: E = pi L r^2 / d^2 facing it;
    // normalized, L / (4 pi r^2). treatAsPoint keeps the sphere's power (exact, one sample).
    const std::string lit = "    float inputs:radius = 0.3\n    float inputs:intensity = 4";
    RGB plain(float(kPiD * 4.0 * 0.09 / 4.0)), normalized(float(4.0 / (4.0 * kPiD * 0.09) * kPiD * 0.09 / 4.0));
    expectIrradiance(downward("SphereLight", lit), kOrigin, kUp, plain);
    expectIrradiance(downward("SphereLight", lit + "\n    bool inputs:normalize = 1"), kOrigin, kUp, normalized);
    expectIrradiance(downward("SphereLight", lit + "\n    bool treatAsPoint = 1"), kOrigin, kUp, plain);
    expectIrradiance(downward("SphereLight", lit + "\n    bool treatAsPoint = 1\n    bool inputs:normalize = 1"),
                     kOrigin, kUp, normalized);
}

TEST(UsdLuxConformance, CylinderNormalizeDividesByItsWorldSideArea) {
    // sizeFactor = the world-space area of the side, 2 pi r l, here with the length scaled 2x.
    const std::string lit =
        "    float inputs:radius = 0.2\n    float inputs:length = 1.5\n    float inputs:intensity = 3";
    Measured plain = irradiance(*lightOf(downward("CylinderLight", lit, "(2, 1, 1)")), kOrigin, kUp);
    Measured normalized = irradiance(
        *lightOf(downward("CylinderLight", lit + "\n    bool inputs:normalize = 1", "(2, 1, 1)")), kOrigin, kUp);
    EXPECT_NEAR(normalized.mean.x * (2.0 * kPiD * 0.2 * 3.0), plain.mean.x, 1e-5 * plain.mean.x);
    // treatAsLine: a line of the same power; far away the two agree, to first order in r / D (the
    // cylinder's lit side is up to r nearer than its axis at distance D = 42): within 2 r / D.
    Vec3f far(0.0f, -40.0f, 0.0f);
    Measured cylinder = irradiance(*lightOf(downward("CylinderLight", lit)), far, kUp);
    Measured line = irradiance(*lightOf(downward("CylinderLight", lit + "\n    bool treatAsLine = 1")), far, kUp);
    EXPECT_NEAR(line.mean.x, cylinder.mean.x, 5.0 * (line.error + cylinder.error) + 2.0 * 0.2 / 42.0 * cylinder.mean.x);
}

TEST(UsdLuxConformance, DistantAngleAndNormalize) {
    // angle 0: a delta light whose L is the irradiance on a surface facing it, times cos.
    std::string tilted =
        "def DistantLight \"Sun\"\n{\n    float inputs:angle = 0\n    float inputs:intensity = 2\n"
        "    float inputs:exposure = -1\n    float3 xformOp:rotateXYZ = (-60, 0, 0)\n"
        "    uniform token[] xformOpOrder = [\"xformOp:rotateXYZ\"]\n}\n";
    expectIrradiance(tilted, kOrigin, kUp, RGB(float(std::cos(30.0 * kDeg))));
    // angle > 0: L is the disk's radiance, E = L pi sin^2(theta_max); normalized, divided by
    // sizeFactor = pi sin^2(theta_max) up to a hemisphere and (2 - sin^2(theta_max)) pi beyond.
    auto sun = [](const std::string& inputs) {
        return "def DistantLight \"Sun\"\n{\n" + inputs +
               "\n    float inputs:intensity = 3\n    float3 xformOp:rotateXYZ = (-90, 0, 0)\n"
               "    uniform token[] xformOpOrder = [\"xformOp:rotateXYZ\"]\n}\n";
    };
    double s5 = std::sin(5.0 * kDeg);
    expectIrradiance(sun("    float inputs:angle = 10"), kOrigin, kUp, RGB(float(3.0 * kPiD * s5 * s5)));
    expectIrradiance(sun("    float inputs:angle = 10\n    bool inputs:normalize = 1"), kOrigin, kUp, RGB(3.0f));
    // 270 degrees: theta_max = 135, sin^2 = 1/2; a facing surface sees a whole hemisphere of it.
    expectIrradiance(sun("    float inputs:angle = 270\n    bool inputs:normalize = 1"), kOrigin, kUp,
                     RGB(float(3.0 / (1.5 * kPiD) * kPiD)));
}

// A point light 2 units up facing down, I = pi r^2 L = pi 0.01 x 100 = pi; the irradiance on the
// floor at angle theta off its axis is I shaping(theta) cos(theta) / d^2, d = 2 / cos(theta).
void expectShaped(const std::string& shaping, const std::function<RGB(double theta)>& factor) {
    std::string usda = downward("SphereLight",
                                "    float inputs:radius = 0.1\n    float inputs:intensity = 100\n"
                                "    bool treatAsPoint = 1\n" +
                                    shaping);
    for (double deg : {0.0, 5.0, 14.0, 20.0, 27.0, 29.5, 35.0, 60.0}) {
        double theta = deg * kDeg, c = std::cos(theta);
        Vec3f p(float(2.0 * std::tan(theta)), 0.0f, 0.0f);
        expectIrradiance(usda, p, kUp, factor(theta) * float(kPiD * c * c * c / 4.0));
    }
}

double smoothstep(double x, double a, double b) {
    if (a >= b) return x < b ? 0.0 : 1.0;
    double t = std::clamp((x - a) / (b - a), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

TEST(UsdLuxConformance, ConeAngleAndSoftness) {
    // 0 beyond the cone; inside, 1 - smoothstep(theta, lerp(softness, cutoff, 0), cutoff), with
    // softness clamped to [0, 1].
    const double cutoff = 30.0 * kDeg;
    expectShaped("    float inputs:shaping:cone:angle = 30",
                 [&](double theta) { return RGB(theta > cutoff ? 0.0f : 1.0f); });
    for (double softness : {0.4, 1.0, 1.8}) {
        double start = (1.0 - std::min(softness, 1.0)) * cutoff;
        expectShaped(
            "    float inputs:shaping:cone:angle = 30\n    float inputs:shaping:cone:softness = " +
                std::to_string(softness),
            [&](double theta) { return RGB(float(theta > cutoff ? 0.0 : 1.0 - smoothstep(theta, start, cutoff))); });
    }
}

TEST(UsdLuxConformance, FocusAndFocusTint) {
    // focusFactor = |cos theta|^focus; the emission times lerp(focusFactor, focusTint, 1).
    const RGB tint(0.5f, 0.2f, 0.0f);
    expectShaped("    float inputs:shaping:focus = 3\n    color3f inputs:shaping:focusTint = (0.5, 0.2, 0)",
                 [&](double theta) {
                     float f = float(std::pow(std::abs(std::cos(theta)), 3.0));
                     return tint * (1.0f - f) + RGB(f);
                 });
    // Behind the light (a 180-degree cone): the absolute value, so the back is focused too.
    std::string usda =
        downward("SphereLight",
                 "    float inputs:radius = 0.1\n    float inputs:intensity = 100\n    bool treatAsPoint = 1\n"
                 "    float inputs:shaping:cone:angle = 180\n    float inputs:shaping:focus = 2");
    Vec3f above(0.0f, 2.0f + std::sqrt(3.0f), 1.0f);  // 30 degrees off the light's back (+Y), distance 2
    Vec3f towardsLight = normalize(Vec3f(0.0f, 2.0f, 0.0f) - above);
    double cos150 = std::cos(150.0 * kDeg);
    expectIrradiance(usda, above, towardsLight, RGB(float(kPiD * cos150 * cos150 / 4.0)));
}

TEST(UsdLuxConformance, ColorTemperatureOf6500KIsWhite) {
    const std::string lit = "    float inputs:radius = 0.3\n    float inputs:intensity = 4\n    bool treatAsPoint = 1";
    RGB plain(float(kPiD * 4.0 * 0.09 / 4.0));
    expectIrradiance(downward("SphereLight", lit + "\n    bool inputs:enableColorTemperature = 1\n"
                                                   "    float inputs:colorTemperature = 6500"),
                     kOrigin, kUp, plain);
    // colorTemperature alone does nothing: only with enableColorTemperature.
    expectIrradiance(downward("SphereLight", lit + "\n    float inputs:colorTemperature = 2000"), kOrigin, kUp, plain);
}

TEST(UsdLuxConformance, DiffuseAndSpecularMultipliersWarn) {
    auto p = populate(downward("SphereLight", "    float inputs:diffuse = 0.5\n    float inputs:specular = 1"));
    auto warned = [&](const std::string& text) {
        return std::any_of(p.warnings.begin(), p.warnings.end(),
                           [&](const std::string& w) { return w.find(text) != std::string::npos; });
    };
    EXPECT_TRUE(warned("/L: inputs:diffuse = 0.5"));
    EXPECT_FALSE(warned("inputs:specular")) << "1 is what Fluence does";
}

}  // namespace
}  // namespace fluence::delegate
