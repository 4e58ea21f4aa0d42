// A textured rect light's importance sampling: directions against pdf() (chi-square and per
// sample), sampled points counted per texel against pdf() and the texels' luminance, the weights
// of negative and non-finite texels, and black and constant textures sampled uniformly. Its
// irradiance against the exact value is in light_irradiance_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "core/sampling.h"
#include "render/light_image_distribution.h"
#include "render/lights/rect_light.h"
#include "tests/render/light_test_support.h"
#include "tests/support/chi2.h"

namespace fluence::render {
namespace {

// The tilted rect of the light tests with `texture`.
LightDesc tiltedRect(std::shared_ptr<const RgbImage> texture) {
    LightDesc d = test::tiltedRectDesc();
    d.name = "/window";
    d.texture = std::move(texture);
    return d;
}

// 8 x 4 texels of varied colours, about 100:1 from the dimmest to the brightest, and one black texel.
std::shared_ptr<RgbImage> colouredTexture() {
    return test::image(
        8, 4, [](int x, int y) { return x == 5 && y == 2 ? RGB(0.0f) : RGB(0.1f + x, 0.5f * y, float((x + y) % 3)); });
}

TEST(RectLightTexture, ImportanceSamplingMatchesPdf) {
    LightDesc d = tiltedRect(colouredTexture());
    d.radiance = RGB(1.0f, 0.5f, 2.0f);
    RectLight light(d);
    test::HitFunction hit = [&](const Vec3f& p, const Vec3f& wi) { return test::hitRect(light, p, wi); };
    for (const Vec3f& p : {Vec3f(0.1f, 0.0f, 0.2f), Vec3f(1.5f, 1.6f, -0.6f)}) {
        auto r = test::chi2SphereTest(test::directionsOf(light, p), test::pdfOf(light, p, hit));
        EXPECT_GT(r.pValue, test::kChi2Alpha) << r.report;
        test::expectSamplesMatchPdf(light, p, hit);
    }
}

// The sphere test above integrates pdf() numerically, which cannot resolve a few texels 1500
// times brighter than the rest; here the samples are counted per texel instead, where the
// density over area is constant and the expected counts are exact. For texel i, with centre
// q_i seen from p along wi at distance d and cosine cos_i at the light: P(i) = pdf(p, wi) cos_i /
// d^2 x texel area, which must also be luminance(radiance x texel i) / the sum over texels.
// Pearson's chi-square over the texels; a black texel gets no samples at all.
void expectSamplesFallOnTexelsAsPdfSays(const LightDesc& desc, const Vec3f& p, int samples) {
    RectLight light(desc);
    const RgbImage& texture = *desc.texture;
    const int w = texture.width, h = texture.height;
    auto c = light.corners();  // c[2] at the texture's top-left, c[3] top-right, c[1] bottom-left
    Vec3f topLeft = c[2], across = c[3] - c[2], down = c[1] - c[2], normal = normalize(cross(across, down));
    double totalLuminance = 0.0;
    for (const RGB& t : texture.texels) totalLuminance += luminance(desc.radiance * t);
    std::vector<double> probability(texture.texels.size());
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            Vec3f q = topLeft + across * ((x + 0.5f) / w) + down * ((y + 0.5f) / h);
            Vec3f wi = normalize(q - p);
            double areaPdf = light.pdf(p, wi, {q, normal}) * std::abs(dot(normal, wi)) / lengthSquared(q - p);
            double& pi = probability[std::size_t(y) * w + x];
            pi = areaPdf * light.area() / (w * h);
            EXPECT_NEAR(pi, luminance(desc.radiance * texture.at(x, y)) / totalLuminance, 1e-4 * pi + 1e-9)
                << "texel " << x << ", " << y;
        }
    std::vector<double> counts(texture.texels.size(), 0.0);
    for (int n = 0; n < samples; ++n) {
        auto s = light.sample(p, SampleStream(5, 0, n).next2D());
        ASSERT_TRUE(s);
        Vec3f q = p + s->wi * s->distance - topLeft;
        int x = std::clamp(int(dot(q, across) / dot(across, across) * w), 0, w - 1);
        int y = std::clamp(int(dot(q, down) / dot(down, down) * h), 0, h - 1);
        counts[std::size_t(y) * w + x] += 1.0;
    }
    double chi2 = 0.0;
    int cells = 0;
    for (std::size_t i = 0; i < counts.size(); ++i) {
        double expected = samples * probability[i];
        if (expected == 0.0) {
            EXPECT_EQ(counts[i], 0.0) << "texel " << i << " has no weight";
            continue;
        }
        chi2 += (counts[i] - expected) * (counts[i] - expected) / expected;
        ++cells;
    }
    EXPECT_GT(test::upperIncompleteGammaQ(0.5 * (cells - 1), 0.5 * chi2), test::kChi2Alpha) << "chi2 = " << chi2;
}

TEST(RectLightTexture, SamplesFallOnTexelsAsPdfSays) {
    LightDesc coloured = tiltedRect(colouredTexture());
    coloured.radiance = RGB(1.0f, 0.5f, 2.0f);
    expectSamplesFallOnTexelsAsPdfSays(coloured, Vec3f(0.1f, 0.0f, 0.2f), 200000);
    // 500 texels of the frame expect about 10 samples each.
    expectSamplesFallOnTexelsAsPdfSays(tiltedRect(test::windowTexture()), Vec3f(1.5f, 1.6f, -0.6f), 200000);
}

TEST(RectLightTexture, NegativeChannelsAndNonFiniteTexelsWeighNothing) {
    const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
    auto texture = test::image(4, 1, [&](int x, int) {
        const RGB texels[] = {RGB(1.0f, -1.0f, 0.0f), RGB(-1.0f), RGB(inf, 0.0f, 0.0f), RGB(nan, 1.0f, 1.0f)};
        return texels[x];
    });
    std::vector<float> weights = luminanceWeights(*texture, RGB(2.0f));
    ASSERT_EQ(weights.size(), 4u);
    EXPECT_FLOAT_EQ(weights[0], luminance(RGB(2.0f, 0.0f, 0.0f)));
    EXPECT_EQ(weights[1], 0.0f);
    EXPECT_EQ(weights[2], 0.0f);
    EXPECT_EQ(weights[3], 0.0f);
    // Such a texture still makes a light: every sample lands on the one texel with weight, and the
    // power counts the others as black.
    RectLight light(tiltedRect(texture));
    EXPECT_FLOAT_EQ(light.power({}), luminance(RGB(3.0f, 0.0f, 0.0f)) / 4.0f * light.area() * kPi);
    for (int n = 0; n < 100; ++n) {
        auto s = light.sample(Vec3f(0, 0, 0), SampleStream(6, 0, n).next2D());
        ASSERT_TRUE(s);
        EXPECT_TRUE(std::isfinite(s->pdf) && s->pdf > 0.0f);
        EXPECT_EQ(s->Li, RGB(3.0f, -3.0f, 0.0f));
    }
}

// A black texture (all weights zero) and a constant one are sampled as the untextured rect is:
// the same points with the same finite densities, and the texture's multiple of its radiance.
TEST(RectLightTexture, BlackAndConstantTexturesAreSampledUniformly) {
    RectLight plain(tiltedRect(nullptr));
    const Vec3f p(0.1f, 0.0f, 0.2f);
    for (float grey : {0.0f, 0.5f}) {
        RectLight light(tiltedRect(test::image(5, 3, [&](int, int) { return RGB(grey); })));
        for (int n = 0; n < 200; ++n) {
            Vec2f u = SampleStream(4, 0, n).next2D();
            auto s = light.sample(p, u), reference = plain.sample(p, u);
            ASSERT_EQ(bool(s), bool(reference)) << "sample " << n;
            if (!s) continue;
            EXPECT_EQ(s->wi, reference->wi) << "sample " << n;
            auto hit = test::hitRect(light, p, s->wi);
            ASSERT_TRUE(hit);
            float uniformPdf = plain.pdf(p, s->wi, *hit);
            EXPECT_NEAR(s->pdf, uniformPdf, 1e-5f * uniformPdf) << "grey " << grey << ", sample " << n;
            EXPECT_NEAR(light.pdf(p, s->wi, *hit), uniformPdf, 1e-5f * uniformPdf)
                << "grey " << grey << ", sample " << n;
            EXPECT_EQ(s->Li, RGB(3.0f * grey));
        }
        EXPECT_FLOAT_EQ(light.power({}), grey * plain.power({}));
    }
}

}  // namespace
}  // namespace fluence::render
