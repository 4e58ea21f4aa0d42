// Shared by the light tests: light textures, where a ray meets a rect light, directions a light
// samples, the consistency of sample() with pdf(), and irradiance estimated from a light's own
// samples.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <memory>
#include <optional>

#include "core/random.h"
#include "render/light.h"
#include "render/lights/rect_light.h"
#include "tests/support/statistics.h"

namespace fluence::test {

using render::Light;
using render::LightHit;

// A 2 x 1 rect of radiance 3 emitting downwards (-Y) from y = 2, tilted a little.
inline render::LightDesc tiltedRectDesc() {
    render::LightDesc d;
    d.name = "/rect";
    d.type = render::LightType::Rect;
    d.width = 2.0f;
    d.height = 1.0f;
    d.radiance = RGB(3.0f);
    d.transform = Matrix4::translate({0.3, 2.0, -0.2}) * Matrix4::rotateZ(10) * Matrix4::rotateX(-90);
    return d;
}

// A width x height image with texel(x, y) at column x, row y (row 0 at the top).
inline std::shared_ptr<render::RgbImage> image(int width, int height, const std::function<RGB(int x, int y)>& texel) {
    auto img = std::make_shared<render::RgbImage>();
    img->width = width;
    img->height = height;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) img->texels.push_back(texel(x, y));
    return img;
}

// A high-contrast rect light texture: a dark grey frame (0.02) around a small warm window
// (40, 30, 20) of 4 x 3 texels, up and to the right of the centre of a 32 x 16 image.
inline std::shared_ptr<render::RgbImage> windowTexture() {
    return image(32, 16, [](int x, int y) {
        return x >= 20 && x < 24 && y >= 3 && y < 6 ? RGB(40.0f, 30.0f, 20.0f) : RGB(0.02f);
    });
}

// Lambert's formula for a polygon of uniform radiance L above p's tangent plane:
// E = L / 2 * |sum_i angle(R_i, R_i+1) * n . normalize(R_i x R_i+1)|, R_i = vertex_i - p.
inline double polygonIrradiance(const std::array<Vec3f, 4>& corners, const Vec3f& p, const Vec3f& n, double radiance) {
    double sum = 0.0;
    for (int i = 0; i < 4; ++i) {
        Vec3d a = normalize(Vec3d(corners[i] - p)), b = normalize(Vec3d(corners[(i + 1) % 4] - p));
        sum += std::acos(std::clamp(dot(a, b), -1.0, 1.0)) * dot(Vec3d(n), normalize(cross(a, b)));
    }
    return 0.5 * radiance * std::abs(sum);
}

// Where the ray p + t wi meets the rect light, if it does: the point and the rect's normal.
inline std::optional<LightHit> hitRect(const render::RectLight& light, const Vec3f& p, const Vec3f& wi) {
    auto c = light.corners();
    Vec3f e1 = c[1] - c[0], e2 = c[3] - c[0];
    Vec3f n = normalize(cross(e1, e2));
    float denom = dot(wi, n);
    if (std::abs(denom) < 1e-8f) return std::nullopt;
    float t = dot(c[0] - p, n) / denom;
    if (t <= 0.0f) return std::nullopt;
    Vec3f q = p + wi * t;
    float a = dot(q - c[0], e1) / dot(e1, e1), b = dot(q - c[0], e2) / dot(e2, e2);
    if (a < 0 || a > 1 || b < 0 || b > 1) return std::nullopt;
    return LightHit{q, n};
}

// Where a ray from p along wi meets the light's surface (for pdf()), if it does.
using HitFunction = std::function<std::optional<LightHit>(const Vec3f& p, const Vec3f& wi)>;

inline std::function<std::optional<Vec3f>(Vec2f)> directionsOf(const Light& light, const Vec3f& p) {
    return [&light, p](Vec2f u) -> std::optional<Vec3f> {
        auto s = light.sample(p, u);
        return s ? std::optional(s->wi) : std::nullopt;
    };
}

// The density pdf() gives the direction wi from p (0 where the ray misses the light).
inline std::function<double(const Vec3f&)> pdfOf(const Light& light, const Vec3f& p, const HitFunction& hit) {
    return [&light, p, hit](const Vec3f& wi) {
        auto h = hit(p, wi);
        return h ? double(light.pdf(p, wi, *h)) : 0.0;
    };
}

// Every sample's pdf matches pdf() at the point it reached, which lies at the sample's distance.
// The density goes as 1/cos at the light, so at grazing samples float rounding in the normal of
// the hit (about 1e-6) moves it by 1e-6 / cos relative: the tolerance allows for that.
inline void expectSamplesMatchPdf(const Light& light, const Vec3f& p, const HitFunction& hit, int count = 2000) {
    int accepted = 0;
    for (int n = 0; n < count; ++n) {
        auto s = light.sample(p, SampleStream(21, 0, n).next2D());
        if (!s) continue;
        ++accepted;
        auto h = hit(p, s->wi);
        ASSERT_TRUE(h) << "sample " << n << " points away from the light";
        EXPECT_NEAR(length(h->point - p), s->distance, 1e-3f * s->distance) << "sample " << n;
        float cosLight = std::abs(dot(h->normal, s->wi));
        EXPECT_NEAR(light.pdf(p, s->wi, *h), s->pdf, s->pdf * (2e-3f + 1e-5f / std::max(cosLight, 1e-6f)))
            << "sample " << n;
    }
    EXPECT_GT(accepted, count / 2);
}

// Irradiance at p on a surface with unit normal n, estimated from `count` light samples.
inline MeanEstimate irradianceEstimate(const Light& light, const Vec3f& p, const Vec3f& n, int count,
                                       std::uint64_t seed = 11) {
    MeanEstimate e;
    for (int i = 0; i < count; ++i) {
        auto s = light.sample(p, SampleStream(seed, 0, i).next2D());
        e.add(s ? double(s->Li.x) * std::max(0.0f, dot(n, s->wi)) / s->pdf : 0.0);
    }
    return e;
}

}  // namespace fluence::test
