// Throughput against the limit (issue #10 item 4): how close the renderer's rays/s come to
// Embree's raw ray-casting rate on the same scene, on this machine.
//
//   embree_throughput_bench [--spp N] [--threads N] [--repeat N] [--scale S] [--sampler NAME] [--minimal]
//                           [--streams] [SCENE.usda ...]
//
// Each scene is loaded as `fluence render` loads it (stage, delegate, colour management,
// render::RenderScene, the camera at the scene's resolution times --scale). Then:
//   raw, renderer's distribution: a path-traced pass's rays, generated with the scene's own
//     camera, light tree and lights: per pixel sample a camera ray; at every surface hit a shadow
//     ray to a light chosen by RenderScene::chooseLight and sampled by the light (stopped short as
//     RenderScene::occluded does) and a cosine-distributed bounce ray, up to 8 bounces (no
//     Russian roulette), stored in path order per image row. Each kind is replayed through bare
//     rtcIntersect1 (camera, bounce) or rtcOccluded1 (shadow) on RenderScene::embreeSurfaces(),
//     over --threads threads with oneTBB, in the stored order: as incoherent as the renderer's.
//     The raw rate is then taken at the renderer's own mix of the three kinds (its counters):
//     1 / sum(share_k / rate_k).
//   raw, uniform: as many rays with origins uniform in the scene's bounding sphere and uniform
//     directions, through rtcIntersect1.
//   renderer: integrators::render() with the `path` integrator, --spp samples per pixel (default
//     16), seed 0, the sampler --sampler names (default the renderer's, sobol), and RenderCounters'
//     rays (camera + bounce + shadow), the count `fluence render` prints. Free-flight and
//     transmittance tracking in media (smoke, subsurface walks) cost time but cast no counted rays:
//     those scenes' ratios include that cost.
//   own cost: beside each ratio, the path tracer's CPU time per ray and per path (camera sample)
//     outside Embree: its time per ray less bare Embree's at the renderer's mix.
//   minimal (--minimal): the ceiling, bench/minimal_path_tracer.h, the leanest honest path tracer
//     with next-event estimation for Lambertian meshes and one rect light (the Cornell box), on
//     the same Embree scene, --spp samples per pixel, seed 1, independent samples; its ratio to the same raw rate says
//     what share of the raw rate any such path tracer keeps once it shades its hits. Its image's
//     mean luminance is printed beside the renderer's (seed 0), with their difference in standard
//     errors (from each pixel's sample variance), to show it renders the same image.
//   streams (--streams): the same stored rays through rtcIntersect1M / rtcOccluded1M in blocks of
//     64 (camera rays flagged coherent), and the ratio the renderer would reach with its own cost
//     per ray unchanged and Embree's time at those rates: for shadow rays alone, and for all rays.
// Rates are rays per CPU-second of the process (all threads; CLOCK_PROCESS_CPUTIME_ID), so that a
// shared, loaded machine slows both sides alike; the renderer's wall-clock rate is printed too.
// Every figure is the best of --repeat runs (default 3); --scale defaults to 0.5. With no scenes
// given, the six benchmark scenes of the issue are measured.
#include <embree3/rtcore.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/image_mean.h"
#include "bench/minimal_path_tracer.h"
#include "color/color_management.h"
#include "core/film.h"
#include "core/frame.h"
#include "core/random.h"
#include "core/sampler_names.h"
#include "core/sampling.h"
#include "delegate/scene_delegate.h"
#include "integrators/integrator.h"
#include "integrators/renderer.h"
#include "render/embree_ray.h"
#include "render/render_scene.h"
#include "scene/stage.h"

namespace {

using namespace fluence;

constexpr int kMaxBounces = 8;
constexpr std::size_t kGrain = 1024;  // rays per TBB task

struct Options {
    int spp = 16, threads = 2, repeat = 3;
    double scale = 0.5;
    bool minimal = false;  // also run bench/minimal_path_tracer.h
    bool streams = false;  // also replay the rays in streams (rtcIntersect1M / rtcOccluded1M)
    SamplerKind sampler = integrators::RenderSettings{}.sampler;
    std::vector<std::string> scenes;
};

struct StoredRay {
    Vec3f origin, direction;
    float tFar;
};

struct RaySet {
    std::vector<StoredRay> camera, bounce;  // closest hit
    std::vector<StoredRay> shadow;          // any hit
    void append(const RaySet& o) {
        camera.insert(camera.end(), o.camera.begin(), o.camera.end());
        bounce.insert(bounce.end(), o.bounce.begin(), o.bounce.end());
        shadow.insert(shadow.end(), o.shadow.begin(), o.shadow.end());
    }
};

// The rays a path-traced pass casts on image row y (see the top of the file).
RaySet renderersRays(const render::RenderScene& scene, const render::Camera& camera, int width, int y, int spp) {
    RaySet set;
    for (int x = 0; x < width; ++x)
        for (int s = 0; s < spp; ++s) {
            SampleStream rng(1, std::uint64_t(y) * width + x, s);
            Vec2f jitter = rng.next2D();
            render::Ray ray = camera.generateRay(x + jitter.x, y + jitter.y);
            for (int depth = 0; depth <= kMaxBounces; ++depth) {
                (depth == 0 ? set.camera : set.bounce).push_back({ray.origin, ray.direction, ray.tMax});
                std::optional<render::SurfaceHit> hit = scene.intersect(ray);
                if (!hit || hit->lightShape) break;
                Vec3f n =
                    dot(hit->geometricNormal, ray.direction) < 0.0f ? hit->geometricNormal : -hit->geometricNormal;
                Vec3f from = render::offsetRayOrigin(hit->point, n);
                render::LightChoice choice = scene.chooseLight(from, n, rng.next());
                if (choice.light >= 0)
                    if (std::optional<render::LightSample> ls = scene.light(choice.light).sample(from, rng.next2D()))
                        if (ls->pdf > 0.0f && dot(ls->wi, n) > 0.0f)
                            set.shadow.push_back({from, ls->wi, ls->distance * (1.0f - bench::kShadowRayShortening)});
                ray = {from, Frame::fromNormal(n).toWorld(sampleCosineHemisphere(rng.next2D())), 0.0f,
                       std::numeric_limits<float>::infinity()};
            }
        }
    return set;
}

// Every row's rays, made in parallel and stored in row order.
RaySet renderersRays(tbb::task_arena& arena, const render::RenderScene& scene, const render::Camera& camera, int width,
                     int height, int spp) {
    std::vector<RaySet> rows(static_cast<std::size_t>(height));
    arena.execute([&] {
        tbb::parallel_for(0, height,
                          [&](int y) { rows[std::size_t(y)] = renderersRays(scene, camera, width, y, spp); });
    });
    RaySet set;
    for (const RaySet& row : rows) set.append(row);
    return set;
}

std::vector<StoredRay> uniformRays(const render::SceneBounds& bounds, std::size_t count) {
    std::vector<StoredRay> rays;
    rays.reserve(count);
    for (std::size_t i = 0; i < count; ++i) {
        SampleStream rng(2, i, 0);
        Vec3f offset = sampleUniformSphere(rng.next2D()) * (bounds.radius * std::cbrt(rng.next()));
        rays.push_back(
            {bounds.centre + offset, sampleUniformSphere(rng.next2D()), std::numeric_limits<float>::infinity()});
    }
    return rays;
}

// CPU seconds of the whole process (every thread): on a shared machine, where this process gets
// only part of the cores, rays per CPU-second measure the code, not the other tenants.
double cpuSeconds() {
    timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

// CPU seconds to trace `rays` through bare Embree over the arena's threads, closest hit or any hit.
double trace(tbb::task_arena& arena, RTCScene scene, const std::vector<StoredRay>& rays, bool anyHit) {
    const double start = cpuSeconds();
    arena.execute([&] {
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rays.size(), kGrain),
                          [&](const tbb::blocked_range<std::size_t>& r) {
                              RTCIntersectContext context;
                              rtcInitIntersectContext(&context);
                              for (std::size_t i = r.begin(); i != r.end(); ++i) {
                                  // Written as the renderer writes its rays (render/embree_ray.h: no store-forwarding stalls).
                                  const StoredRay& s = rays[i];
                                  if (anyHit) {
                                      RTCRay ray;
                                      render::storeRay(ray, s.origin, s.direction, 0.0f, s.tFar);
                                      rtcOccluded1(scene, &context, &ray);
                                  } else {
                                      RTCRayHit hit;
                                      render::storeRayHit(hit, s.origin, s.direction, 0.0f, s.tFar);
                                      rtcIntersect1(scene, &context, &hit);
                                  }
                              }
                          });
    });
    return cpuSeconds() - start;
}

// CPU seconds to trace `rays` through Embree's stream queries (rtcIntersect1M, rtcOccluded1M) in
// blocks of kStream consecutive rays (stored order: a tile's rays of one kind, as a renderer that
// queued them would pass them), `coherent` telling Embree that neighbours start and point alike.
constexpr std::size_t kStream = 64;
double traceStreams(tbb::task_arena& arena, RTCScene scene, const std::vector<StoredRay>& rays, bool anyHit,
                    bool coherent) {
    const double start = cpuSeconds();
    arena.execute([&] {
        tbb::parallel_for(
            tbb::blocked_range<std::size_t>(0, rays.size(), kGrain), [&](const tbb::blocked_range<std::size_t>& r) {
                RTCIntersectContext context;
                rtcInitIntersectContext(&context);
                context.flags = coherent ? RTC_INTERSECT_CONTEXT_FLAG_COHERENT : RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
                RTCRayHit hits[kStream];
                RTCRay shadows[kStream];
                for (std::size_t b = r.begin(); b < r.end(); b += kStream) {
                    const std::size_t n = std::min(kStream, r.end() - b);
                    for (std::size_t i = 0; i < n; ++i) {
                        const StoredRay& s = rays[b + i];
                        if (anyHit)
                            render::storeRay(shadows[i], s.origin, s.direction, 0.0f, s.tFar);
                        else
                            render::storeRayHit(hits[i], s.origin, s.direction, 0.0f, s.tFar);
                    }
                    if (anyHit)
                        rtcOccluded1M(scene, &context, shadows, unsigned(n), sizeof(RTCRay));
                    else
                        rtcIntersect1M(scene, &context, hits, unsigned(n), sizeof(RTCRayHit));
                }
            });
    });
    return cpuSeconds() - start;
}

// A path tracer's own cost (issue #25 item 5): its CPU time per ray less bare Embree's at the same
// mix of ray kinds, i.e. what it spends outside Embree, per ray and per path (one per camera ray).
std::string ownCost(double mraysPerCpuSecond, double rawMraysPerCpuSecond, double rays, double paths) {
    const double perRay = 1e3 / mraysPerCpuSecond - 1e3 / rawMraysPerCpuSecond;  // ns
    char text[160];
    std::snprintf(text, sizeof text, "outside Embree %.1f ns per ray, %.0f ns per path (%.2f rays per path)", perRay,
                  perRay * rays / paths, rays / paths);
    return text;
}

template <typename F>
double best(int repeat, F&& f) {
    double b = f();
    for (int i = 1; i < repeat; ++i) b = std::min(b, f());
    return b;
}

// --minimal: bench/minimal_path_tracer.h on the same scene, against the same raw rate (see the top
// of the file); a scene it does not handle is reported and skipped.
void measureMinimal(const render::RenderScene& scene, const render::Camera& camera, int width, int height,
                    const Options& opt, tbb::task_arena& arena, double raw, double renderer,
                    const bench::ImageMean& rendererMean, const integrators::RenderCounters& rendererCounters) {
    std::optional<bench::MinimalPathTracer> made;
    try {
        made.emplace(scene, integrators::IntegratorSettings{}.maxDepth);
    } catch (const std::invalid_argument& e) {
        std::printf("  minimal path tracer: not run (%s)\n\n", e.what());
        return;
    }
    bench::MinimalRender m;
    double minimal = 0.0;
    for (int i = 0; i < opt.repeat; ++i) {
        const double start = cpuSeconds();
        m = made->render(arena, camera, width, height, opt.spp, 1);
        minimal = std::max(minimal, m.rays() / (cpuSeconds() - start) * 1e-6);
    }
    std::printf(
        "  minimal path tracer: rays camera/bounce/shadow %llu/%llu/%llu  Mrays per CPU-s %.2f  ratio %.3f "
        "(renderer's %.3f)\n  minimal's own cost: %s\n",
        (unsigned long long)m.camera, (unsigned long long)m.bounce, (unsigned long long)m.shadow, minimal,
        minimal / raw, renderer / raw, ownCost(minimal, raw, double(m.rays()), double(m.camera)).c_str());
    std::printf(
        "  image mean luminance: renderer %.6f +- %.6f  minimal %.6f +- %.6f  difference %.2f standard errors"
        "  (RGB renderer %.5f %.5f %.5f, minimal %.5f %.5f %.5f; non-finite samples %llu/%llu)\n\n",
        rendererMean.luminance, rendererMean.standardError, m.mean.luminance, m.mean.standardError,
        bench::standardErrorsApart(m.mean, rendererMean), rendererMean.rgb.x, rendererMean.rgb.y, rendererMean.rgb.z,
        m.mean.rgb.x, m.mean.rgb.y, m.mean.rgb.z, (unsigned long long)rendererCounters.nonFiniteSamples,
        (unsigned long long)m.nonFiniteSamples);
}

void measure(const std::string& path, const Options& opt, color::ColorManagement& colors) {
    auto stage = usd::Stage::open(path);
    delegate::DelegateOptions dopt;
    dopt.time = stage->startTimeCode().value_or(usd::kDefaultTime);
    dopt.convertColor = [&](const RGB& c, const std::string& space) { return colors.toRenderingSpace(space, c); };
    dopt.warn = [](const std::string&, const std::string&) {};
    delegate::DelegateResult populated = delegate::populateScene(*stage, dopt);
    const int width = std::max(1, int(populated.resolution.first * opt.scale));
    const int height = std::max(1, int(populated.resolution.second * opt.scale));
    dopt.resolution = std::pair(width, height);
    populated = delegate::populateScene(*stage, dopt);  // diced for the resolution rendered
    render::RenderScene scene(populated.scene, std::make_shared<texture::TextureSystem>(colors));
    render::Camera camera(*populated.scene.camera, width, height, populated.framing);
    scene.setTextureFilterCamera(camera);

    tbb::task_arena arena(opt.threads);
    RaySet rays = renderersRays(arena, scene, camera, width, height, opt.spp);
    const std::size_t generated = rays.camera.size() + rays.bounce.size() + rays.shadow.size();
    std::vector<StoredRay> uniform = uniformRays(scene.bounds(), generated);
    RTCScene embree = scene.embreeSurfaces();
    auto rate = [&](const std::vector<StoredRay>& set, bool anyHit) {
        return set.size() / best(opt.repeat, [&] { return trace(arena, embree, set, anyHit); }) * 1e-6;
    };
    const double rCamera = rate(rays.camera, false), rBounce = rate(rays.bounce, false),
                 rShadow = rate(rays.shadow, true);
    const double rUniform = rate(uniform, false);

    auto integrator = integrators::findIntegrator("path")->create({});
    integrators::RenderStats stats;
    double renderer = 0.0, rendererWall = 0.0;  // per CPU-second, per second
    bench::ImageMean rendererMean;
    for (int i = 0; i < opt.repeat; ++i) {
        integrators::RenderSettings settings;
        settings.samplesPerPixel = opt.spp;
        settings.sampler = opt.sampler;
        settings.threads = opt.threads;
        Film film(width, height, camera.farClip());
        const double start = cpuSeconds();
        stats = integrators::render(scene, camera, *integrator, settings, film);
        renderer = std::max(renderer, stats.counters.rays() / (cpuSeconds() - start) * 1e-6);
        rendererWall = std::max(rendererWall, stats.counters.rays() / stats.seconds * 1e-6);
        if (opt.minimal) rendererMean = bench::filmMean(film);
    }
    const auto& c = stats.counters;
    const double n = double(c.rays());
    // Bare Embree's rate on the renderer's mix: the time per ray of each kind, weighted by its share.
    const double raw = 1.0 / (c.camera / n / rCamera + c.bounce / n / rBounce + c.shadow / n / rShadow);
    std::printf("%s  (%dx%d, %d spp, %zu triangles, %zu instances, %d threads, renderer's sampler %s)\n", path.c_str(),
                width, height, opt.spp, scene.stats().triangles, scene.stats().instances, opt.threads,
                std::string(samplerName(opt.sampler)).c_str());
    std::printf("  rays camera/bounce/shadow  generated %zu/%zu/%zu  renderer %llu/%llu/%llu\n", rays.camera.size(),
                rays.bounce.size(), rays.shadow.size(), (unsigned long long)c.camera, (unsigned long long)c.bounce,
                (unsigned long long)c.shadow);
    std::printf("  raw Mrays per CPU-s: camera %.2f  bounce %.2f  shadow (occluded) %.2f  uniform %.2f\n", rCamera,
                rBounce, rShadow, rUniform);
    std::printf(
        "  Mrays per CPU-s: raw at the renderer's mix %.2f  renderer %.2f  ratio %.3f   (renderer wall-clock %.2f "
        "Mrays/s)\n  renderer's own cost: %s; Embree %.1f ns per ray\n\n",
        raw, renderer, renderer / raw, rendererWall, ownCost(renderer, raw, n, double(c.camera)).c_str(), 1e3 / raw);
    if (opt.streams) {
        // What streams would give the renderer: its time per ray outside Embree kept, Embree's
        // part at the stream rates (camera rays coherent, bounce and shadow rays not).
        auto streamRate = [&](const std::vector<StoredRay>& set, bool anyHit, bool coherent) {
            return set.size() / best(opt.repeat, [&] { return traceStreams(arena, embree, set, anyHit, coherent); }) *
                   1e-6;
        };
        const double sCamera = streamRate(rays.camera, false, true), sBounce = streamRate(rays.bounce, false, false),
                     sShadow = streamRate(rays.shadow, true, false);
        const double own = 1.0 / renderer - 1.0 / raw;  // microseconds per ray
        const double shadowOnly = own + c.camera / n / rCamera + c.bounce / n / rBounce + c.shadow / n / sShadow;
        const double all = own + c.camera / n / sCamera + c.bounce / n / sBounce + c.shadow / n / sShadow;
        std::printf(
            "  streams of %zu, Mrays per CPU-s: camera (coherent) %.2f  bounce %.2f  shadow (occluded) %.2f\n"
            "  projected ratio with the renderer's own cost kept: shadow rays streamed %.3f, all rays streamed "
            "%.3f\n\n",
            kStream, sCamera, sBounce, sShadow, 1.0 / shadowOnly / raw, 1.0 / all / raw);
    }
    if (opt.minimal) measureMinimal(scene, camera, width, height, opt, arena, raw, renderer, rendererMean, c);
}

}  // namespace

int main(int argc, char** argv) {
    Options opt;
    for (int i = 1; i < argc; ++i) {
        std::string arg = argv[i];
        auto number = [&] { return i + 1 < argc ? std::atof(argv[++i]) : 0.0; };
        if (arg == "--spp")
            opt.spp = std::max(1, int(number()));
        else if (arg == "--threads")
            opt.threads = std::max(1, int(number()));
        else if (arg == "--repeat")
            opt.repeat = std::max(1, int(number()));
        else if (arg == "--scale")
            opt.scale = std::max(0.01, number());
        else if (arg == "--minimal")
            opt.minimal = true;
        else if (arg == "--streams")
            opt.streams = true;
        else if (arg == "--sampler" && i + 1 < argc && samplerNamed(argv[i + 1]))
            opt.sampler = *samplerNamed(argv[++i]);
        else if (!arg.empty() && arg[0] != '-')
            opt.scenes.push_back(arg);
        else {
            std::fprintf(stderr,
                         "usage: embree_throughput_bench [--spp N] [--threads N] [--repeat N] [--scale S] "
                         "[--sampler sobol|independent] [--minimal] [--streams] [SCENE.usda ...]\n");
            return 2;
        }
    }
    if (opt.scenes.empty())
        for (const char* s : {"usd_samples/cornell_box.usda", "usd_samples/material_ball/material_ball.usda",
                              "usd_samples/subdivision/creased_cubes.usda", "usd_samples/smoke/smoke.usda",
                              "usd_samples/subsurface/subsurface.usda", "bench/scenes/caustic_glass.usda"})
            opt.scenes.push_back(std::string(FLUENCE_SOURCE_DIR) + "/" + s);
    try {
        color::ColorManagement colors = color::ColorManagement::load();
        for (const std::string& scene : opt.scenes) measure(scene, opt, colors);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "embree_throughput_bench: %s\n", e.what());
        return 1;
    }
    return 0;
}
