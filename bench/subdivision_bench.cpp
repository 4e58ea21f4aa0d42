// Subdivision benchmark: what camera-driven dicing costs and buys, on
// usd_samples/subdivision/creased_cubes.usda (three creased Catmull-Clark cubes on a floor).
//
//   subdivision_bench [--scene FILE.usda] [--spp N]
//
// Part 1, dicing against distance: the camera backs away along its view line (distance x1/2 .. x8
// of the sample's); for each distance the delegate describes the scene (every subdivision
// surface diced at 1 pixel per micro-edge for a 960x640 image): triangles, tessellation time,
// triangles/s, and the bytes the tessellated meshes take (positions, indices, normals, colours).
// Part 2, speed against accuracy: a 480x320 image at --spp (default 16) samples, same seed, for
// uniform refinement (--subdiv-level 1..5) and camera-driven dicing (rates 4, 2, 1 pixels); each
// image's RMS error against a reference diced at 0.25 pixels with the same seed (so the noise
// largely cancels and what remains is mostly the tessellation's error), with the time to
// tessellate, build and render. One process; VmHWM is printed at the end.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

#include "bench/process_status.h"
#include "core/film.h"
#include "delegate/scene_delegate.h"
#include "integrators/integrator.h"
#include "integrators/renderer.h"
#include "render/render_scene.h"
#include "scene/stage.h"

namespace {

using namespace fluence;
using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

delegate::DelegateOptions optionsFor(std::pair<int, int> resolution, const delegate::DicingSettings& dicing) {
    delegate::DelegateOptions o;
    o.resolution = resolution;
    o.dicing = dicing;
    o.convertColor = [](const RGB& c, const std::string&) { return c; };
    o.warn = [](const std::string& path, const std::string& message) {
        std::fprintf(stderr, "warning: %s: %s\n", path.c_str(), message.c_str());
    };
    return o;
}

struct Tessellated {
    render::SceneDescription scene;
    double seconds = 0.0;
    std::size_t triangles = 0, bytes = 0;
};

// Describes the stage (dicing every subdivision surface), timing only sceneDescription().
Tessellated tessellate(delegate::SceneDelegate& delegate) {
    Tessellated t;
    auto start = Clock::now();
    t.scene = delegate.sceneDescription();
    t.seconds = secondsSince(start);
    for (const render::MeshDesc& m : t.scene.meshes) {
        t.triangles += m.indices.size() / 3;
        t.bytes += m.positions.size() * sizeof(Vec3f) + m.indices.size() * sizeof(std::uint32_t) +
                   m.cornerNormals.size() * sizeof(Vec3f) + m.cornerColors.size() * sizeof(RGB);
    }
    return t;
}

void distances(usd::Stage& stage) {
    std::printf("Part 1: dicing against distance (960x640, 1 pixel per micro-edge)\n\n");
    std::printf("%9s  %11s  %9s  %12s  %10s\n", "distance", "triangles", "dice s", "Mtriangles/s", "MiB");
    for (double k : {0.5, 1.0, 2.0, 4.0, 8.0}) {
        // The sample's camera sits at (0, 2.2, 5.2) looking down 20 degrees: back away along that line.
        stage.setAttribute("/Scene/Camera", "xformOp:translate",
                           usd::Value::numeric("double3", {0.0, 2.2 * k, 5.2 * k}, 3, false));
        delegate::SceneDelegate delegate(stage, optionsFor({960, 640}, {}));
        delegate.sync();
        Tessellated t = tessellate(delegate);
        std::printf("%8.1fx  %11zu  %9.3f  %12.2f  %10.1f\n", k, t.triangles, t.seconds, t.triangles / t.seconds * 1e-6,
                    t.bytes / 1048576.0);
    }
    stage.setAttribute("/Scene/Camera", "xformOp:translate", usd::Value::numeric("double3", {0.0, 2.2, 5.2}, 3, false));
}

struct Rendered {
    Image image;
    std::size_t triangles = 0;
    double dice = 0.0, build = 0.0, render = 0.0;
};

Rendered renderWith(usd::Stage& stage, const delegate::DicingSettings& dicing, int spp) {
    Rendered r;
    delegate::SceneDelegate delegate(stage, optionsFor({480, 320}, dicing));
    delegate.sync();
    Tessellated t = tessellate(delegate);
    r.triangles = t.triangles;
    r.dice = t.seconds;
    auto start = Clock::now();
    render::RenderScene scene(t.scene);
    render::Camera camera(*t.scene.camera, 480, 320);
    r.build = secondsSince(start);
    auto integrator = integrators::integratorRegistry().front().create({});
    integrators::RenderSettings settings;
    settings.samplesPerPixel = spp;
    settings.seed = 1;
    Film film(480, 320, camera.farClip());
    r.render = integrators::render(scene, camera, *integrator, settings, film).seconds;
    r.image = film.resolve();
    return r;
}

double rmsError(const Image& a, const Image& reference) {
    double sum = 0.0;
    std::size_t n = 0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x)
            for (const char* c : {"R", "G", "B"}) {
                int i = a.channelIndex(c);
                double d = a.pixels[(static_cast<std::size_t>(y) * a.width + x) * a.channelCount() + i] -
                           reference.pixels[(static_cast<std::size_t>(y) * a.width + x) * reference.channelCount() + i];
                sum += d * d;
                ++n;
            }
    return std::sqrt(sum / n);
}

void speedAgainstAccuracy(usd::Stage& stage, int spp) {
    std::printf("\nPart 2: speed against accuracy (480x320, %d spp, seed 1, integrator %s)\n\n", spp,
                integrators::integratorRegistry().front().name.c_str());
    delegate::DicingSettings referenceDicing;
    referenceDicing.rate = 0.25f;
    Rendered reference = renderWith(stage, referenceDicing, spp);
    std::printf("reference: dicing rate 0.25 px, %zu triangles, render %.2f s\n\n", reference.triangles,
                reference.render);
    std::printf("%-18s  %11s  %8s  %8s  %9s  %9s  %10s\n", "tessellation", "triangles", "dice s", "build s", "render s",
                "total s", "RMS error");
    auto row = [&](const std::string& name, const delegate::DicingSettings& dicing) {
        Rendered r = renderWith(stage, dicing, spp);
        std::printf("%-18s  %11zu  %8.3f  %8.3f  %9.3f  %9.3f  %10.5f\n", name.c_str(), r.triangles, r.dice, r.build,
                    r.render, r.dice + r.build + r.render, rmsError(r.image, reference.image));
    };
    for (int level = 1; level <= 5; ++level) {
        delegate::DicingSettings uniform;
        uniform.uniformLevel = level;
        row("--subdiv-level " + std::to_string(level), uniform);
    }
    for (float rate : {4.0f, 2.0f, 1.0f}) {
        delegate::DicingSettings adaptive;
        adaptive.rate = rate;
        char name[32];
        std::snprintf(name, sizeof name, "--dicing-rate %g", rate);
        row(name, adaptive);
    }
}

}  // namespace

int main(int argc, char** argv) {
    std::string scene = std::string(FLUENCE_SOURCE_DIR) + "/usd_samples/subdivision/creased_cubes.usda";
    int spp = 16;
    for (int i = 1; i < argc; ++i) {
        std::string arg = argv[i];
        if (arg == "--scene" && i + 1 < argc)
            scene = argv[++i];
        else if (arg == "--spp" && i + 1 < argc)
            spp = std::max(1, std::atoi(argv[++i]));
        else {
            std::fprintf(stderr, "usage: subdivision_bench [--scene FILE.usda] [--spp N]\n");
            return 2;
        }
    }
    try {
        auto stage = usd::Stage::open(scene);
        std::printf("scene: %s\n\n", scene.c_str());
        distances(*stage);
        speedAgainstAccuracy(*stage, spp);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "subdivision_bench: %s\n", e.what());
        return 1;
    }
    std::printf("\npeak resident memory (VmHWM): %.1f MiB\n", bench::statusKiB("VmHWM") / 1024.0);
    return 0;
}
