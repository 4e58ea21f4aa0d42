// Emission driven by a texture or a primvar (render/textured_emission.h): what rays that hit the
// emitter see, what next-event estimation samples on it (the same function of the point), the
// irradiance it gives by either strategy against Lambert's formula, and the per-triangle power
// that light selection and the light tree choose its triangles by.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>

#include "core/frame.h"
#include "core/random.h"
#include "core/sampling.h"
#include "render/render_scene.h"
#include "tests/render/light_test_support.h"
#include "tests/support/scenes.h"
#include "tests/support/statistics.h"
#include "tests/support/temp_dir.h"
#include "tests/texture/image_writer.h"

namespace fluence::render {
namespace {

constexpr float kWhite = 2.0f;  // the radiance of the emitter's white texels

// The square [-1, 1]^2 at z = 1 as `columns` quads side by side along x (two triangles each), with
// st = ((x + 1) / 2, (y + 1) / 2) and the face colour `faceColour(column)` as the corner primvar
// displayColor (uniform per quad, as a per-face primvar arrives from the delegate).
MeshDesc emitter(
    int columns, const std::function<RGB(int)>& faceColour = [](int) { return RGB(0.0f); }) {
    MeshDesc m;
    m.name = "/Screen";
    m.material = 0;
    CornerPrimvar st{"st", 2, {}}, colour{"displayColor", 3, {}};
    for (int c = 0; c < columns; ++c) {
        const float x0 = -1.0f + 2.0f * float(c) / float(columns), x1 = -1.0f + 2.0f * float(c + 1) / float(columns);
        const std::uint32_t first = static_cast<std::uint32_t>(m.positions.size());
        for (const Vec3f& p : {Vec3f(x0, -1, 1), Vec3f(x1, -1, 1), Vec3f(x1, 1, 1), Vec3f(x0, 1, 1)})
            m.positions.push_back(p);
        for (std::uint32_t corner : {0u, 1u, 2u, 0u, 2u, 3u}) {
            m.indices.push_back(first + corner);
            const Vec3f& p = m.positions[first + corner];
            st.values.insert(st.values.end(), {(p.x + 1.0f) / 2.0f, (p.y + 1.0f) / 2.0f});
            const RGB f = faceColour(c);
            colour.values.insert(colour.values.end(), {f.x, f.y, f.z});
        }
    }
    m.primvars = {st, colour};
    return m;
}

InputBinding emissionFromTexture(const std::string& file) {
    InputBinding b;
    b.input = MaterialInput::Emission;
    b.channels = 3;
    b.texture.emplace().file = file;
    b.texture->filter = texture::Filter::Closest;  // texel edges stay sharp: Lambert's formula per region is exact
    b.texture->colorSpace = texture::SourceColorSpace::Raw;
    return b;
}

InputBinding emissionFromPrimvar(const std::string& name) {
    InputBinding b;
    b.input = MaterialInput::Emission;
    b.channels = 3;
    b.primvar = name;
    return b;
}

SceneDescription sceneWith(const MeshDesc& mesh, const InputBinding& emission) {
    SceneDescription s;
    MaterialDesc m = test::diffuseMaterial("/Emitter", RGB(0.0f));
    m.bindings.push_back(emission);
    s.materials.push_back(m);
    s.meshes.push_back(mesh);
    return s;
}

class TexturedEmission : public ::testing::Test {
protected:
    // An n x n RGB image, texel (x, y) (row 0 at the top) of radiance kWhite * texel(x, y).
    std::string image(const std::string& name, int n, const std::function<float(int x, int y)>& texel) {
        std::vector<float> pixels;
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) pixels.insert(pixels.end(), 3, kWhite * texel(x, y));
        const std::string path = dir.file(name + ".exr");
        test::writeImage<float>(path, n, n, 3, OIIO::TypeDesc::FLOAT, pixels);
        return path;
    }
    // 8 x 8 checks, white where x + y is odd.
    std::string checkerboard() {
        return image("checks", 8, [](int x, int y) { return float((x + y) % 2); });
    }
    // Black over s < 1/2, white over s >= 1/2.
    std::string halfWhite() {
        return image("half", 16, [](int x, int) { return x >= 8 ? 1.0f : 0.0f; });
    }
    test::TempDir dir{"fluence_textured_emission"};
};

// The radiance of the checkerboard at (x, y) of the emitter.
float checkAt(float x, float y) {
    const int column = static_cast<int>((x + 1.0f) / 2.0f * 8.0f),
              rowFromBottom = static_cast<int>((y + 1.0f) / 2.0f * 8.0f);
    return kWhite * float((column + (7 - rowFromBottom)) % 2);
}

TEST_F(TexturedEmission, RaysThatHitTheEmitterSeeItsTexture) {
    RenderScene scene(sceneWith(emitter(1), emissionFromTexture(checkerboard())));
    EXPECT_TRUE(scene.warnings().empty());
    EXPECT_EQ(scene.stats().emissiveTriangles, 2u);
    int white = 0;
    for (int i = 0; i < 8; ++i)
        for (int j = 0; j < 8; ++j) {
            const float x = -1.0f + (float(i) + 0.5f) / 4.0f, y = -1.0f + (float(j) + 0.5f) / 4.0f;
            std::optional<SurfaceHit> hit = scene.intersect(Ray{{x, y, 0.0f}, {0.0f, 0.0f, 1.0f}});
            ASSERT_TRUE(hit);
            ASSERT_GE(hit->light, 0) << "the emitter's triangles are lights";
            EXPECT_EQ(hit->emission, RGB(checkAt(x, y))) << x << ", " << y;
            white += hit->emission.x > 0.0f;
        }
    EXPECT_EQ(white, 32) << "half the checks are white";
}

// Next-event estimation's radiance at the point it samples is what a ray along the sampled
// direction finds there: one function, so MIS weighs the same radiance either way.
TEST_F(TexturedEmission, LightSamplesCarryTheRadianceRaysFindAtTheSamePoint) {
    RenderScene scene(sceneWith(emitter(1), emissionFromTexture(checkerboard())));
    const Vec3f p(0.3f, -0.2f, 0.0f), n(0.0f, 0.0f, 1.0f);
    int black = 0, white = 0;
    for (int i = 0; i < 2000; ++i) {
        SampleStream stream(5, 0, std::uint64_t(i));
        const LightChoice choice = scene.chooseLight(p, n, stream.next());
        ASSERT_GE(choice.light, 0);
        const Light& light = scene.light(std::size_t(choice.light));
        std::optional<LightSample> s = light.sample(p, stream.next2D());
        ASSERT_TRUE(s);
        std::optional<SurfaceHit> hit = scene.intersect(Ray{p, s->wi});
        ASSERT_TRUE(hit);
        EXPECT_NEAR(hit->t, s->distance, 1e-4f);
        // Away from the checks' edges, where a ray's rounding may cross to the next texel.
        const float u = (hit->point.x + 1.0f) * 4.0f, v = (hit->point.y + 1.0f) * 4.0f;
        if (std::abs(u - std::round(u)) < 1e-3f || std::abs(v - std::round(v)) < 1e-3f) continue;
        EXPECT_EQ(s->Li, hit->emission);
        EXPECT_EQ(light.emitted({hit->point, hit->geometricNormal}, -s->wi), hit->emission);
        (hit->emission.x > 0.0f ? white : black) += 1;
    }
    EXPECT_GT(black, 500);
    EXPECT_GT(white, 500);
}

// Irradiance on a point below a screen whose left half is black and right half white is that of
// the white half alone (Lambert's formula), estimated by light sampling alone and by cosine-weighted
// (BSDF) sampling alone; each within five standard errors of its own spread.
TEST_F(TexturedEmission, IrradianceIsTheWhiteHalfsByLightSamplingAndByBsdfSampling) {
    // One quad: each of its two triangles is half black, half white (the diagonal crosses the split).
    RenderScene scene(sceneWith(emitter(1), emissionFromTexture(halfWhite())));
    const Vec3f p(-0.2f, 0.3f, 0.0f), n(0.0f, 0.0f, 1.0f);
    const double expected =
        test::polygonIrradiance({Vec3f(0, -1, 1), Vec3f(1, -1, 1), Vec3f(1, 1, 1), Vec3f(0, 1, 1)}, p, n, kWhite);
    constexpr int kSamples = 100000;
    test::MeanEstimate byLights, byBsdf;
    for (int i = 0; i < kSamples; ++i) {
        SampleStream stream(17, 0, std::uint64_t(i));
        const LightChoice choice = scene.chooseLight(p, n, stream.next());
        std::optional<LightSample> s =
            choice.light >= 0 ? scene.light(std::size_t(choice.light)).sample(p, stream.next2D()) : std::nullopt;
        byLights.add(s ? double(s->Li.x) * std::max(0.0f, dot(n, s->wi)) / (s->pdf * choice.probability) : 0.0);
        const Vec3f wi = Frame::fromNormal(n).toWorld(sampleCosineHemisphere(stream.next2D()));
        std::optional<SurfaceHit> hit = scene.intersect(Ray{p, normalize(wi)});
        byBsdf.add(hit ? double(hit->emission.x) * kPi : 0.0);  // L cos / (cos / pi)
    }
    EXPECT_NEAR(byLights.mean(), expected, 5.0 * byLights.standardError());
    EXPECT_NEAR(byBsdf.mean(), expected, 5.0 * byBsdf.standardError());
    EXPECT_LT(byLights.standardError(), byBsdf.standardError()) << "light sampling is the better strategy here";
}

// The emitter's triangles keep reading its mesh when the meshes stored after it move it in memory.
TEST_F(TexturedEmission, SurvivesTheMeshesStoredAfterIt) {
    SceneDescription s = sceneWith(emitter(1), emissionFromTexture(checkerboard()));
    for (int i = 0; i < 40; ++i)
        s.meshes.push_back(test::quadMesh("/Far" + std::to_string(i),
                                          {Vec3f(float(i), 0, -5), Vec3f(float(i) + 0.5f, 0, -5),
                                           Vec3f(float(i) + 0.5f, 0.5f, -5), Vec3f(float(i), 0.5f, -5)},
                                          -1));
    RenderScene scene(s);
    EXPECT_EQ(scene.intersect(Ray{{-0.875f, 0.875f, 0.0f}, {0.0f, 0.0f, 1.0f}})->emission,
              RGB(checkAt(-0.875f, 0.875f)));
    EXPECT_EQ(scene.intersect(Ray{{-0.625f, 0.875f, 0.0f}, {0.0f, 0.0f, 1.0f}})->emission,
              RGB(checkAt(-0.625f, 0.875f)));
    EXPECT_GT(scene.light(0).power(scene.bounds()), 0.0f);
}

// Per-triangle power: with the screen's halves as separate quads, the black half's triangles are
// never chosen, by power or by the light tree, and the white half's share all the probability.
// Uniform selection would give each triangle 1/4 and waste half the samples on black.
TEST_F(TexturedEmission, DarkTrianglesAreNotChosen) {
    const Vec3f p(-0.2f, 0.3f, 0.0f), n(0.0f, 0.0f, 1.0f);
    auto expectOnlyWhiteChosen = [&](const RenderScene& scene, float tolerance) {
        ASSERT_EQ(scene.lightCount(), 4u);  // quad 0 (triangles 0, 1) black, quad 1 (2, 3) white
        for (std::size_t t = 0; t < 4; ++t) {
            EXPECT_NEAR(scene.lightSelection().pmf(t), t < 2 ? 0.0f : 0.5f, tolerance) << "triangle " << t;
            if (t < 2) {
                EXPECT_NEAR(scene.lightProbability(p, n, int(t)), 0.0f, tolerance) << "triangle " << t;
            }
        }
        EXPECT_NEAR(scene.lightProbability(p, n, 2) + scene.lightProbability(p, n, 3), 1.0f, tolerance);
    };
    // displayColor per face: exact.
    expectOnlyWhiteChosen(RenderScene(sceneWith(emitter(2, [](int c) { return RGB(c == 1 ? kWhite : 0.0f); }),
                                                emissionFromPrimvar("displayColor"))),
                          0.0f);
    // The texture: each triangle's mean from its sub-triangles' mip-filtered lookups.
    expectOnlyWhiteChosen(RenderScene(sceneWith(emitter(2), emissionFromTexture(halfWhite()))), 1e-3f);
}

// A triangle's power is its mean radiance times its area and 2 pi (both sides): a texture of
// three quarters white gives three quarters of the constant emitter's power.
TEST_F(TexturedEmission, TrianglePowerIsThatOfItsMeanRadiance) {
    const std::string file = image("quarters", 16, [](int x, int y) { return x < 8 && y < 8 ? 0.0f : 1.0f; });
    RenderScene textured(sceneWith(emitter(1), emissionFromTexture(file)));
    SceneDescription constant;
    constant.materials.push_back(test::diffuseMaterial("/Emitter", RGB(0.0f), RGB(kWhite)));
    constant.meshes.push_back(emitter(1));
    RenderScene uniform(constant);
    const float total = textured.light(0).power(textured.bounds()) + textured.light(1).power(textured.bounds());
    const float full = uniform.light(0).power(uniform.bounds()) + uniform.light(1).power(uniform.bounds());
    EXPECT_NEAR(total / full, 0.75f, 0.02f);
}

// The same emission seen by rays: a primvar reader of displayColor per face.
TEST_F(TexturedEmission, PrimvarEmissionIsSeenPerFace) {
    RenderScene scene(sceneWith(emitter(2, [](int c) { return c == 0 ? RGB(1, 0, 0) : RGB(0, 0, 3); }),
                                emissionFromPrimvar("displayColor")));
    EXPECT_EQ(scene.intersect(Ray{{-0.5f, 0.2f, 0.0f}, {0, 0, 1}})->emission, RGB(1, 0, 0));
    EXPECT_EQ(scene.intersect(Ray{{0.5f, -0.2f, 0.0f}, {0, 0, 1}})->emission, RGB(0, 0, 3));
}

}  // namespace
}  // namespace fluence::render
