// Light selection and dome-light sampling benchmark.
//
//   many_lights_bench [--points P] [--samples S]
//
// Many lights: a 40 x 40 floor under N = 10, 100, 1000 sphere and rect lights (random positions
// 0.5-3 units up, radii 0.05-0.15, sizes 0.1-0.4, radiance spread over two decades). At P floor
// points (default 512) S next-event samples (default 256) each estimate the irradiance: choose a
// light (power-proportional, RenderScene::lightSelection(), or the light tree,
// RenderScene::chooseLight()), sample it, and cast the shadow ray. Figures per method: nanoseconds
// per choice alone and per sample (one thread; choice + light sample + shadow ray), and the
// relative variance of one
// sample, the mean over points of (X - E)^2 / E^2, where E is the point's irradiance summed over
// every light from 16 samples of each (so a rare, large sample is weighed against the true mean
// rather than the noisy mean of the point's own samples). Their product (lower is better) is the
// time a given noise level costs.
//
// Dome: a 1024 x 512 lat-long sky (a gradient from 0.2 at the horizon to 1 at the zenith, black
// below, and a 3 x 3-texel sun of 50,000 at 37 degrees elevation), irradiance on surfaces facing
// up, towards the sun's side (-X) and away from it (+X), from 1,000,000 samples of the dome's
// importance sampler and of uniform directions: the relative standard deviation of one sample
// and nanoseconds per sample.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include "core/random.h"
#include "core/sampling.h"
#include "render/lights/dome_light.h"
#include "render/render_scene.h"
#include "tests/support/statistics.h"

namespace {

using namespace fluence;
using Clock = std::chrono::steady_clock;

render::SceneDescription manyLights(int count) {
    render::SceneDescription scene;
    render::MeshDesc floor;
    floor.name = "/floor";
    floor.positions = {Vec3f(-20, 0, -20), Vec3f(20, 0, -20), Vec3f(20, 0, 20), Vec3f(-20, 0, 20)};
    floor.indices = {0, 2, 1, 0, 3, 2};
    scene.meshes.push_back(floor);
    SampleStream rng(2026, 0, 0);
    for (int i = 0; i < count; ++i) {
        render::LightDesc d;
        d.name = "/light" + std::to_string(i);
        d.type = i % 2 ? render::LightType::Sphere : render::LightType::Rect;
        d.radius = 0.05f + 0.1f * rng.next();
        d.width = 0.1f + 0.3f * rng.next();
        d.height = 0.1f + 0.3f * rng.next();
        d.radiance = RGB(std::pow(100.0f, rng.next()));
        double x = 40.0 * rng.next() - 20.0, y = 0.5 + 2.5 * rng.next(), z = 40.0 * rng.next() - 20.0;
        d.transform = Matrix4::translate({x, y, z}) * Matrix4::rotateX(-90.0 + 60.0 * (rng.next() - 0.5));
        scene.lights.push_back(d);
    }
    return scene;
}

struct Figures {
    double nsPerChoice = 0.0, nsPerSample = 0.0, relativeVariance = 0.0;
};

const Vec3f kUp(0, 1, 0);

Vec3f floorPoint(int i) {
    SampleStream where(7, std::uint64_t(i), 0);
    return {36.0f * where.next() - 18.0f, 1e-4f, 36.0f * where.next() - 18.0f};
}

// One next-event sample of the irradiance at p from light `light` chosen with `probability`.
double nextEventSample(const render::RenderScene& scene, const Vec3f& p, int light, float probability, Vec2f u) {
    if (light < 0) return 0.0;
    auto ls = scene.light(light).sample(p, u);
    if (!ls || !(ls->pdf > 0.0f) || ls->wi.y <= 0.0f || scene.occluded(p, ls->wi, ls->distance)) return 0.0;
    return luminance(ls->Li) * ls->wi.y / (probability * ls->pdf);
}

// Each point's irradiance: every light, 16 samples each.
std::vector<double> referenceIrradiance(const render::RenderScene& scene, int points) {
    std::vector<double> reference(points, 0.0);
    for (int i = 0; i < points; ++i)
        for (std::size_t light = 0; light < scene.lightCount(); ++light)
            for (int k = 0; k < 16; ++k)
                reference[i] +=
                    nextEventSample(scene, floorPoint(i), int(light), 1.0f, SampleStream(3, light, k).next2D()) / 16.0;
    return reference;
}

Figures nextEventEstimate(const render::RenderScene& scene, const std::vector<double>& reference, int samples,
                          const std::function<render::LightChoice(const Vec3f&, const Vec3f&, float)>& choose) {
    std::vector<double> squaredError(reference.size(), 0.0);
    auto start = Clock::now();
    for (std::size_t i = 0; i < reference.size(); ++i) {
        Vec3f p = floorPoint(int(i));
        for (int s = 0; s < samples; ++s) {
            SampleStream rng(11, i, std::uint64_t(s));
            render::LightChoice c = choose(p, kUp, rng.next());
            double error = nextEventSample(scene, p, c.light, c.probability, rng.next2D()) - reference[i];
            squaredError[i] += error * error;
        }
    }
    double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    // The choices alone, again.
    float sink = 0.0f;
    start = Clock::now();
    for (std::size_t i = 0; i < reference.size(); ++i)
        for (int s = 0; s < samples; ++s)
            sink += choose(floorPoint(int(i)), kUp, SampleStream(11, i, std::uint64_t(s)).next()).probability;
    double choiceSeconds = std::chrono::duration<double>(Clock::now() - start).count();
    if (sink < 0.0f) std::puts("");  // keeps the choices observable
    double relativeVariance = 0.0;
    int counted = 0;
    for (std::size_t i = 0; i < reference.size(); ++i)
        if (reference[i] > 0.0) {
            relativeVariance += squaredError[i] / samples / (reference[i] * reference[i]);
            ++counted;
        }
    double count = double(reference.size()) * samples;
    return {choiceSeconds * 1e9 / count, seconds * 1e9 / count, counted ? relativeVariance / counted : 0.0};
}

void benchManyLights(int points, int samples) {
    std::printf("lights  method  ns/choice  ns/sample  relative variance  cost (ns/sample x variance)\n");
    for (int count : {10, 100, 1000}) {
        render::RenderScene scene(manyLights(count));
        std::vector<double> reference = referenceIrradiance(scene, points);
        Figures power = nextEventEstimate(scene, reference, samples, [&](const Vec3f&, const Vec3f&, float u) {
            std::size_t i = scene.lightSelection().sample(u);
            return render::LightChoice{int(i), scene.lightSelection().pmf(i)};
        });
        Figures tree = nextEventEstimate(scene, reference, samples, [&](const Vec3f& p, const Vec3f& n, float u) {
            return scene.chooseLight(p, n, u);
        });
        for (auto [name, f] : {std::pair{"power", power}, std::pair{"tree", tree}})
            std::printf("%6d  %-6s  %9.1f  %9.1f  %17.2f  %27.0f\n", count, name, f.nsPerChoice, f.nsPerSample,
                        f.relativeVariance, f.nsPerSample * f.relativeVariance);
    }
}

void benchDome() {
    auto sky = std::make_shared<render::RgbImage>();
    sky->width = 1024;
    sky->height = 512;
    for (int y = 0; y < sky->height; ++y)
        for (int x = 0; x < sky->width; ++x) {
            bool sun = std::abs(x - 700) <= 1 && std::abs(y - 150) <= 1;
            float zenith = std::max(0.0f, 1.0f - float(y) / (0.5f * sky->height));
            sky->texels.push_back(sun ? RGB(50000.0f) : RGB(0.2f + 0.8f * zenith));
        }
    render::LightDesc d;
    d.type = render::LightType::Dome;
    d.texture = sky;
    render::DomeLight dome(d);
    constexpr int kN = 1000000;
    std::printf("\nnormal     sampler     irradiance  relative sd / sample  ns/sample\n");
    for (auto [name, n] :
         {std::pair{"up", Vec3f(0, 1, 0)}, std::pair{"-X (sun)", Vec3f(-1, 0, 0)}, std::pair{"+X", Vec3f(1, 0, 0)}}) {
        for (bool importance : {true, false}) {
            test::MeanEstimate e;
            auto start = Clock::now();
            for (int i = 0; i < kN; ++i) {
                Vec2f u = SampleStream(5, 0, std::uint64_t(i)).next2D();
                double value = 0.0;
                if (importance) {
                    if (auto s = dome.sample(Vec3f(0.0f), u))
                        value = luminance(s->Li) * std::max(0.0f, dot(n, s->wi)) / s->pdf;
                } else {
                    Vec3f wi = sampleUniformSphere(u);
                    value = luminance(dome.escaped(wi)) * std::max(0.0f, dot(n, wi)) / kUniformSpherePdf;
                }
                e.add(value);
            }
            double ns = std::chrono::duration<double, std::nano>(Clock::now() - start).count() / kN;
            std::printf("%-9s  %-10s  %10.3f  %20.3f  %9.1f\n", name, importance ? "importance" : "uniform", e.mean(),
                        e.standardError() * std::sqrt(double(kN)) / e.mean(), ns);
        }
    }
}

}  // namespace

int main(int argc, char** argv) {
    int points = 512, samples = 256;
    for (int i = 1; i + 1 < argc; i += 2) {
        if (!std::strcmp(argv[i], "--points"))
            points = std::atoi(argv[i + 1]);
        else if (!std::strcmp(argv[i], "--samples"))
            samples = std::atoi(argv[i + 1]);
    }
    benchManyLights(points, samples);
    benchDome();
}
