#include "integrators/first_hit_aovs.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <limits>

#include "core/random.h"

namespace fluence::integrators {

namespace {

using Value = std::array<float, 4>;

// The camera's worldToNdc at the shutter's opening and close (the same for a still camera).
struct Projections {
    Matrix4 open, close;
};

// Where a world point lands on the image, in pixels from its top-left corner (`toNdc`: the camera's
// worldToNdc).
Vec2f rasterOf(const render::Camera& camera, const Matrix4& toNdc, const Vec3f& p) {
    const double x = toNdc.m[0][0] * p.x + toNdc.m[0][1] * p.y + toNdc.m[0][2] * p.z + toNdc.m[0][3];
    const double y = toNdc.m[1][0] * p.x + toNdc.m[1][1] * p.y + toNdc.m[1][2] * p.z + toNdc.m[1][3];
    const double w = toNdc.m[3][0] * p.x + toNdc.m[3][1] * p.y + toNdc.m[3][2] * p.z + toNdc.m[3][3];
    return {float(x / w * camera.imageWidth()), float(y / w * camera.imageHeight())};
}

// One AOV's value for one camera sample (`hit` null: a miss).
Value sampleValue(const FirstHitAov& aov, const render::RenderScene& scene, const render::Camera& camera,
                  const Projections& toNdc, const render::Ray& ray, const render::SurfaceHit* hit) {
    Value v{0.0f, 0.0f, 0.0f, 0.0f};
    if (!hit) {
        if (aov.source == FirstHitSource::Depth) v[0] = camera.farClip();
        return v;
    }
    switch (aov.source) {
        case FirstHitSource::Depth: v[0] = camera.viewDepth(hit->point); break;
        case FirstHitSource::Normal: {
            const Vec3f n = dot(hit->shadingNormal, ray.direction) > 0.0f ? -hit->shadingNormal : hit->shadingNormal;
            v = {n.x, n.y, n.z, 0.0f};
            break;
        }
        case FirstHitSource::Albedo:
            if (!hit->lightShape)
                v = {hit->material.diffuse[0], hit->material.diffuse[1], hit->material.diffuse[2], 0.0f};
            break;
        case FirstHitSource::Primvar: {
            float value[4] = {0.0f, 0.0f, 0.0f, 0.0f};
            const int k = scene.primvarAt(*hit, aov.primvar, value);
            for (int c = 0; c < std::min(k, 4); ++c) v[std::size_t(c)] = value[c];
            break;
        }
        case FirstHitSource::MotionVector: {
            // Where the point is at each end of the shutter, seen by the camera where it is then.
            const Vec2f open = rasterOf(camera, toNdc.open, scene.pointAt(*hit, 0.0f));
            const Vec2f close = rasterOf(camera, toNdc.close, scene.pointAt(*hit, 1.0f));
            v = {close.x - open.x, open.y - close.y, 0.0f, 0.0f};  // raster y grows downwards
            break;
        }
    }
    return v;
}

// A pixel's running result for one AOV.
struct Accumulator {
    double sum[4] = {0, 0, 0, 0};
    Value best{0.0f, 0.0f, 0.0f, 0.0f};
    float bestDepth = std::numeric_limits<float>::infinity();
    bool anyHit = false;

    void add(PixelFilter filter, const Value& v, bool hit, float depth) {
        for (std::size_t c = 0; c < 4; ++c) sum[c] += v[c];
        if (!hit) return;
        switch (filter) {
            case PixelFilter::Box: break;
            case PixelFilter::Min:
            case PixelFilter::Max:
                for (std::size_t c = 0; c < 4; ++c)
                    best[c] = !anyHit                      ? v[c]
                              : filter == PixelFilter::Min ? std::min(best[c], v[c])
                                                           : std::max(best[c], v[c]);
                break;
            case PixelFilter::Closest:
                if (depth < bestDepth) {
                    best = v;
                    bestDepth = depth;
                }
                break;
        }
        anyHit = true;
    }
};

}  // namespace

Image renderFirstHitAovs(const render::RenderScene& scene, const render::Camera& camera, const RenderSettings& settings,
                         const Film& film, const std::vector<FirstHitAov>& aovs) {
    std::vector<std::string> channels;
    for (std::size_t a = 0; a < aovs.size(); ++a)
        for (int c = 0; c < aovs[a].components; ++c) channels.push_back(std::to_string(a) + "." + std::to_string(c));
    Image image(film.width(), film.height(), channels);
    if (aovs.empty()) return image;
    const std::uint64_t imageWidth = std::uint64_t(settings.imageWidth > 0 ? settings.imageWidth : film.width());
    const Projections toNdc{camera.at(0.0f).worldToNdc(), camera.at(1.0f).worldToNdc()};
    const std::vector<Value> missValues = [&] {
        std::vector<Value> values;
        for (const FirstHitAov& aov : aovs)
            values.push_back(sampleValue(aov, scene, camera, toNdc, render::Ray{}, nullptr));
        return values;
    }();

    tbb::task_arena arena(settings.threads > 0 ? settings.threads : tbb::task_arena::automatic);
    arena.execute([&] {
        tbb::parallel_for(tbb::blocked_range<int>(0, film.height()), [&](const tbb::blocked_range<int>& rows) {
            std::vector<Accumulator> pixel(aovs.size());
            for (int y = rows.begin(); y != rows.end(); ++y)
                for (int x = 0; x < film.width(); ++x) {
                    std::fill(pixel.begin(), pixel.end(), Accumulator{});
                    const int imageX = x + settings.windowX, imageY = y + settings.windowY;
                    const std::uint64_t pixelIndex = std::uint64_t(imageY) * imageWidth + std::uint64_t(imageX);
                    const std::uint32_t samples = film.samples(x, y);
                    for (std::uint32_t s = 0; s < samples; ++s) {
                        SampleStream rng(settings.seed, pixelIndex, std::uint64_t(s), settings.sampler);
                        const render::Ray ray = cameraSampleRay(scene, camera, rng, imageX, imageY);  // the renderer's
                        const std::optional<render::SurfaceHit> hit = scene.intersect(ray);
                        const float depth = hit ? camera.viewDepth(hit->point) : camera.farClip();
                        for (std::size_t a = 0; a < aovs.size(); ++a)
                            pixel[a].add(aovs[a].filter,
                                         sampleValue(aovs[a], scene, camera, toNdc, ray, hit ? &*hit : nullptr),
                                         hit.has_value(), depth);
                    }
                    float* out = image.pixel(x, y);
                    for (std::size_t a = 0; a < aovs.size(); ++a) {
                        const Accumulator& acc = pixel[a];
                        for (int c = 0; c < aovs[a].components; ++c) {
                            const std::size_t k = std::size_t(c);
                            *out++ = aovs[a].filter == PixelFilter::Box
                                         ? (samples > 0 ? float(acc.sum[k] / samples) : missValues[a][k])
                                     : acc.anyHit ? acc.best[k]
                                                  : missValues[a][k];
                        }
                    }
                }
        });
    });
    return image;
}

}  // namespace fluence::integrators
