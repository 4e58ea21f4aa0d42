// Textured rect light benchmark: sampling the texture by luminance (RectLight::sample) against
// uniform area sampling (the sampler RectLight had before), for the direct light on a floor.
//
//   rect_texture_bench [--points P] [--samples S]
//
// A 2 x 1.5 m rect light 2 m above a floor, facing down, with one of three 128 x 96 textures,
// in the open or over a ball of radius 0.4 that shadows part of the floor:
//   window - a small bright window (16 x 12 texels of (20, 18, 15), 1.6% of the area) in a dark
//            frame (0.01): 97% of the power is in the window;
//   panes  - four panes of 0.8 in a thin dark frame (0.002), like the sample scene's
//            usd_samples/lights/textures/window.png;
//   white  - constant 1, which RectLight samples uniformly itself.
// At P floor points (default 64, spread over 4 x 4 m under the light) S next-event samples
// (default 4096) of each method estimate the irradiance: sample a point on the light, cast the
// shadow ray through RenderScene. The reference at each point is the mean of 2^18 importance
// samples (unbiased: the render tests hold that sampler to the exact per-texel Lambert sum).
// Figures per method: nanoseconds per sample (one thread, the fastest of five passes), the
// relative variance of one sample (the mean over points of (X - E)^2 / E^2), the measured RMS
// relative error of 16-sample estimates, and, from the variance and the time, the RMS relative
// error in the time 16 uniform samples take. Last, the cost of ImageDistribution::sample alone
// on each texture's luminance (1,000,000 samples, the fastest of five passes).
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <memory>
#include <vector>

#include "core/random.h"
#include "render/light_image_distribution.h"
#include "render/lights/rect_light.h"
#include "render/render_scene.h"
#include "tests/support/scenes.h"

namespace {

using namespace fluence;
using Clock = std::chrono::steady_clock;

constexpr int kWidth = 128, kHeight = 96;

std::shared_ptr<render::RgbImage> makeTexture(const std::function<RGB(int x, int y)>& texel) {
    auto image = std::make_shared<render::RgbImage>();
    image->width = kWidth;
    image->height = kHeight;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) image->texels.push_back(texel(x, y));
    return image;
}

render::SceneDescription scene(std::shared_ptr<const render::RgbImage> image, bool ball) {
    render::SceneDescription s;
    s.materials.push_back(test::diffuseMaterial("/grey", RGB(0.5f)));
    if (ball) {
        s.meshes.push_back(test::sphereMesh(0.4f, 32, 16, 0));
        for (Vec3f& v : s.meshes.back().positions) v += Vec3f(0.3f, 0.9f, 0.2f);
    }
    render::LightDesc d;
    d.name = "/light";
    d.type = render::LightType::Rect;
    d.width = 2.0f;
    d.height = 1.5f;
    d.radiance = RGB(10.0f);
    d.transform = Matrix4::translate({0.0, 2.0, 0.0}) * Matrix4::rotateX(-90);  // emits downwards
    d.texture = std::move(image);
    s.lights.push_back(d);
    return s;
}

Vec3f floorPoint(int i) {
    SampleStream where(7, std::uint64_t(i), 0);
    return {4.0f * where.next() - 2.0f, 1e-4f, 4.0f * where.next() - 2.0f};
}

// One next-event sample of the irradiance at p (luminance) by the light's own sampler.
double importanceSample(const render::RenderScene& scene, const render::RectLight& rect, const Vec3f& p, Vec2f u) {
    auto s = rect.sample(p, u);
    if (!s || s->wi.y <= 0.0f || scene.occluded(p, s->wi, s->distance)) return 0.0;
    return luminance(s->Li) * s->wi.y / s->pdf;
}

// The sampler RectLight had before importance sampling, outside it: a point uniform over the
// rect's area, and the texel there by emitted() (which solves for the texture coordinates).
class UniformSampler {
public:
    UniformSampler(const render::RenderScene& scene, const render::RectLight& rect)
        : scene_(scene), rect_(rect), corners_(rect.corners()) {
        normal_ = normalize(cross(corners_[1] - corners_[0], corners_[3] - corners_[0]));  // away from the lit side
    }

    double operator()(const Vec3f& p, Vec2f u) const {
        Vec3f q = corners_[0] + (corners_[1] - corners_[0]) * u.x + (corners_[3] - corners_[0]) * u.y;
        Vec3f d = q - p;
        float dist2 = lengthSquared(d), dist = std::sqrt(dist2);
        Vec3f wi = d / dist;
        float cosLight = dot(normal_, wi);
        if (cosLight <= 0.0f || wi.y <= 0.0f || scene_.occluded(p, wi, dist)) return 0.0;
        return luminance(rect_.emitted({q, normal_}, -wi)) * wi.y * cosLight * rect_.area() / dist2;
    }

private:
    const render::RenderScene& scene_;
    const render::RectLight& rect_;
    std::array<Vec3f, 4> corners_;
    Vec3f normal_;
};

struct Figures {
    double nsPerSample = 0.0, relativeVariance = 0.0, rms16 = 0.0;
};

// `estimator(p, u)`: one sample of the irradiance at p from the uniform numbers u.
template <typename Estimator>
Figures measure(const Estimator& estimator, const std::vector<double>& reference, int samples) {
    constexpr int kGroup = 16;
    std::vector<double> values(std::size_t(reference.size()) * samples);
    // The machine is shared: the fastest of five identical passes is the one least disturbed.
    double seconds = 1e30;
    for (int pass = 0; pass < 5; ++pass) {
        auto start = Clock::now();
        for (std::size_t i = 0; i < reference.size(); ++i) {
            Vec3f p = floorPoint(int(i));
            for (int s = 0; s < samples; ++s)
                values[i * samples + s] = estimator(p, SampleStream(11, i, std::uint64_t(s)).next2D());
        }
        seconds = std::min(seconds, std::chrono::duration<double>(Clock::now() - start).count());
    }
    double variance = 0.0, squared16 = 0.0;
    int lit = 0, groups = 0;
    for (std::size_t i = 0; i < reference.size(); ++i) {
        const double e = reference[i];
        if (!(e > 0.0)) continue;  // in the ball's umbra: no relative error to speak of
        ++lit;
        for (int s = 0; s < samples; ++s) variance += std::pow(values[i * samples + s] / e - 1.0, 2) / samples;
        for (int g = 0; g + kGroup <= samples; g += kGroup, ++groups) {
            double sum = 0.0;
            for (int k = 0; k < kGroup; ++k) sum += values[i * samples + g + k];
            squared16 += std::pow(sum / kGroup / e - 1.0, 2);
        }
    }
    return {seconds * 1e9 / double(values.size()), variance / lit, std::sqrt(squared16 / groups)};
}

// Nanoseconds per ImageDistribution::sample on the image's luminance.
double distributionNs(const render::RgbImage& image) {
    render::ImageDistribution d(image.width, image.height, render::luminanceWeights(image, RGB(1.0f)));
    constexpr int kN = 1000000;
    std::vector<Vec2f> us(kN);
    for (int i = 0; i < kN; ++i) us[i] = SampleStream(5, 0, std::uint64_t(i)).next2D();
    double best = 1e30, sink = 0.0;
    for (int pass = 0; pass < 5; ++pass) {
        auto start = Clock::now();
        for (const Vec2f& u : us) sink += d.sample(u).pdf;
        best = std::min(best, std::chrono::duration<double, std::nano>(Clock::now() - start).count() / kN);
    }
    if (sink < 0.0) std::puts("");  // keeps the samples observable
    return best;
}

}  // namespace

int main(int argc, char** argv) {
    int points = 64, samples = 4096;
    for (int i = 1; i + 1 < argc; i += 2) {
        if (!std::strcmp(argv[i], "--points"))
            points = std::atoi(argv[i + 1]);
        else if (!std::strcmp(argv[i], "--samples"))
            samples = std::atoi(argv[i + 1]);
    }
    auto window = [](int x, int y) {
        return x >= 24 && x < 40 && y >= 20 && y < 32 ? RGB(20.0f, 18.0f, 15.0f) : RGB(0.01f);
    };
    auto panes = [](int x, int y) {
        bool frame = x < 6 || x >= 122 || y < 6 || y >= 90 || (x >= 61 && x < 67) || (y >= 45 && y < 51);
        return frame ? RGB(0.002f) : RGB(0.8f);
    };
    auto white = [](int, int) { return RGB(1.0f); };
    const std::pair<const char*, std::shared_ptr<render::RgbImage>> textures[] = {
        {"window", makeTexture(window)}, {"panes", makeTexture(panes)}, {"white", makeTexture(white)}};
    constexpr int kReferenceSamples = 1 << 18;
    std::printf(
        "texture  ball  sampler     ns/sample  relative variance  RMS error, 16 spp  RMS error, time of 16 uniform "
        "spp\n");
    for (bool ball : {false, true})
        for (const auto& [name, image] : textures) {
            render::RenderScene scene(::scene(image, ball));
            const auto& rect = dynamic_cast<const render::RectLight&>(scene.light(0));
            auto importance = [&](const Vec3f& p, Vec2f u) { return importanceSample(scene, rect, p, u); };
            std::vector<double> reference(points, 0.0);
            for (int i = 0; i < points; ++i)
                for (int s = 0; s < kReferenceSamples; ++s)
                    reference[i] +=
                        importance(floorPoint(i), SampleStream(3, i, std::uint64_t(s)).next2D()) / kReferenceSamples;
            Figures is = measure(importance, reference, samples);
            Figures uniform = measure(UniformSampler(scene, rect), reference, samples);
            const double budget = 16.0 * uniform.nsPerSample;  // the time of 16 uniform samples
            for (auto [sampler, f] : {std::pair{"importance", is}, std::pair{"uniform", uniform}})
                std::printf("%-7s  %-4s  %-10s  %9.1f  %17.3f  %17.4f  %33.4f\n", name, ball ? "yes" : "no", sampler,
                            f.nsPerSample, f.relativeVariance, f.rms16,
                            std::sqrt(f.relativeVariance * f.nsPerSample / budget));
        }
    std::printf("\ntexture  ns per ImageDistribution::sample\n");
    for (const auto& [name, image] : textures) std::printf("%-7s  %5.1f\n", name, distributionNs(*image));
}
