// Majorant grid benchmark: what the per-cell majorants of volumes/majorant_grid.h save over one
// global majorant, along camera rays through smoke.
//
//   majorant_grid_bench [--stride N]      (every N-th pixel in x and y; default 2)
//
// Two volumes, each seen by its scene's camera (one ray through every N-th pixel centre, to
// infinity; the ground is ignored): usd_samples/smoke/smoke.vdb, the tools/make_smoke plume, at
// densityScale 6 through the camera of usd_samples/smoke/smoke.usda (320 x 400); and, when it is
// there, the Cycles peer's smoke.vdb (shared/peers/cycles) at density 8 through its camera (256 x
// 256). For each majorant grid (the global majorant, i.e. one cell; cells of 16, 8 (the default) and
// 4 voxels; pbrt-v4's fixed 16^3), over the rays that meet the volume's support:
//   - cells/ray and segments/ray: cells the DDA steps through, and the non-empty ones it yields;
//   - collisions/ray: the sum over segments of sigmaMaj * length, the expected number of tentative
//     collisions ratio tracking draws to cross the volume (a shadow ray's transmittance), and its
//     ratio to the mean optical depth tau (the real collisions' share; 1 would be a perfect
//     majorant);
//   - residual/ray: the same sum over sigmaMaj - sigmaMin, with the grid's minorants as the
//     control: the tentative collisions residual ratio tracking draws, and its ratio to tau;
//   - ns/ray: the DDA alone (one thread), and the grid's build time and size; and, to weigh them,
//     the time of one density lookup (what each tentative collision costs), at random points.
// tau is integrated along each ray by the midpoint rule at a quarter of a voxel.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "bench/camera_rays.h"
#include "core/matrix.h"
#include "core/random.h"
#include "volumes/majorant_grid.h"
#include "volumes/vdb_grid.h"

namespace {

using namespace fluence;
using namespace fluence::volumes;
using Clock = std::chrono::steady_clock;

volatile float gSink;  // where timed loops leave a result, so that they are not optimised away

using Ray = fluence::bench::CameraRay;
using fluence::bench::cameraRays;

struct Config {
    const char* name;
    MajorantGridOptions options;
};

void run(const char* title, const FloatVdbGrid& grid, float densityScale, const std::vector<Ray>& rays) {
    const IndexBox& box = *grid.activeVoxels();
    Vec3i support = box.hi - box.lo + Vec3i(2);
    double voxel = length(Vec3d(grid.indexToWorld().transformVector({1.0, 0.0, 0.0})));
    std::printf("\n%s\n  support %d x %d x %d voxels of %.4g, max density %.3f, density scale %g, %zu camera rays\n",
                title, support.x, support.y, support.z, voxel, grid.maxValue(), densityScale, rays.size());

    // Optical depth along every ray that meets the support (the global grid's one segment spans it).
    MajorantGrid global(grid, {8.0, 1});
    std::vector<double> tau(rays.size(), -1.0);
    double tauSum = 0.0;
    int hits = 0;
    for (std::size_t r = 0; r < rays.size(); ++r) {
        MajorantDda dda(global, rays[r].origin, rays[r].direction, 0.0f, INFINITY, RGB(1.0f));
        std::optional<media::MajorantSegment> s = dda.next();
        if (!s) continue;
        double step = voxel / 4.0, depth = 0.0;
        int n = std::max(1, int(std::ceil((s->tMax - s->tMin) / step)));
        double dt = (s->tMax - s->tMin) / n;
        for (int k = 0; k < n; ++k)
            depth +=
                grid.sample(rays[r].origin + rays[r].direction * float(s->tMin + (k + 0.5) * dt)) * densityScale * dt;
        tau[r] = depth;
        tauSum += depth;
        ++hits;
    }
    // What a tentative collision costs: one density lookup, at random points of the bounds.
    WorldBounds b = grid.worldBounds();
    SampleStream random(3, 0, 0);
    float sink = 0.0f;
    constexpr int kLookups = 1000000;
    auto start = Clock::now();
    for (int k = 0; k < kLookups; ++k)
        sink += grid.sample(b.lo + Vec3f(random.next(), random.next(), random.next()) * (b.hi - b.lo));
    double lookupNs = std::chrono::duration<double, std::nano>(Clock::now() - start).count() / kLookups;
    gSink = sink;
    std::printf("  %d rays meet the support; mean optical depth tau %.4f; a density lookup takes %.1f ns\n\n", hits,
                tauSum / hits, lookupNs);
    std::printf("  %-18s %-10s %9s %8s %10s %13s %15s %9s %13s %9s %9s\n", "majorant", "cells", "build ms", "KB",
                "cells/ray", "segments/ray", "collisions/ray", "/ tau", "residual/ray", "/ tau", "ns/ray");

    const Config configs[] = {{"global (1 cell)", {8.0, 1}},
                              {"16 voxels/cell", {16.0, 1024}},
                              {"8 voxels/cell *", {8.0, 64}},
                              {"4 voxels/cell", {4.0, 1024}},
                              {"16^3 (pbrt-v4)", {1.0, 16}}};
    for (const Config& config : configs) {
        start = Clock::now();
        MajorantGrid majorants(grid, config.options);
        double buildMs = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
        const Vec3i& n = majorants.resolution();
        double cells = 0.0, segments = 0.0, collisions = 0.0, residual = 0.0;
        for (std::size_t r = 0; r < rays.size(); ++r) {
            if (tau[r] < 0.0) continue;
            MajorantDda dda(majorants, rays[r].origin, rays[r].direction, 0.0f, INFINITY, RGB(densityScale),
                            RGB(densityScale));
            while (std::optional<media::MajorantSegment> s = dda.next()) {
                segments += 1.0;
                collisions += double(s->sigmaMaj.x) * (s->tMax - s->tMin);
                residual += double(s->sigmaMaj.x - s->sigmaMin.x) * (s->tMax - s->tMin);
            }
            cells += dda.cellsVisited();
        }
        // The DDA alone, timed over every ray (misses included, as a renderer would see them).
        start = Clock::now();
        for (const Ray& ray : rays) {
            MajorantDda dda(majorants, ray.origin, ray.direction, 0.0f, INFINITY, RGB(densityScale), RGB(densityScale));
            while (std::optional<media::MajorantSegment> s = dda.next()) sink += s->tMax + s->sigmaMin.x;
        }
        double ns = std::chrono::duration<double, std::nano>(Clock::now() - start).count() / double(rays.size());
        gSink = sink;
        char resolution[32];
        std::snprintf(resolution, sizeof resolution, "%dx%dx%d", n.x, n.y, n.z);
        std::printf("  %-18s %-10s %9.2f %8.1f %10.2f %13.2f %15.3f %9.3f %13.3f %9.3f %9.1f\n", config.name,
                    resolution, buildMs, double(n.x) * n.y * n.z * 2 * sizeof(float) / 1024.0, cells / hits,
                    segments / hits, collisions / hits, collisions / tauSum, residual / hits, residual / tauSum, ns);
    }
}

}  // namespace

int main(int argc, char** argv) {
    int stride = 2;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--stride") == 0 && i + 1 < argc) {
            stride = std::max(1, std::atoi(argv[++i]));
        } else {
            std::fprintf(stderr, "usage: majorant_grid_bench [--stride N]\n");
            return 2;
        }
    }
    const std::string ours = FLUENCE_SOURCE_DIR "/usd_samples/smoke/smoke.vdb";
    // usd_samples/smoke/smoke.usda's camera: at (0.3, 1.6, 7.5) tilted 2 degrees down, apertures
    // 19.2 x 24 at focal length 30, 320 x 400 pixels; Y up.
    const float tilt = 2.0f * 3.14159265f / 180.0f;
    run("usd_samples/smoke/smoke.vdb (tools/make_smoke, seed 1)", FloatVdbGrid(ours, "density"), 6.0f,
        cameraRays({0.3f, 1.6f, 7.5f}, Vec3f(0.3f, 1.6f - std::sin(tilt), 7.5f - std::cos(tilt)), {0.0f, 1.0f, 0.0f},
                   9.6f / 30.0f, 12.0f / 30.0f, 320, 400, stride));

    const std::string peer = FLUENCE_SOURCE_DIR "/../shared/peers/cycles/smoke.vdb";
    if (std::filesystem::exists(peer)) {
        // The peer's smoke scene: camera at (0, -5, 1.3) looking at (0, 0, 1.25), Z up, 36 degrees
        // vertical field of view, 256 x 256 pixels.
        float t = std::tan(18.0f * 3.14159265f / 180.0f);
        run("shared/peers/cycles/smoke.vdb (the Cycles peer's plume)", FloatVdbGrid(peer, "density"), 8.0f,
            cameraRays({0.0f, -5.0f, 1.3f}, {0.0f, 0.0f, 1.25f}, {0.0f, 0.0f, 1.0f}, t, t, 256, 256, stride));
    } else {
        std::printf("\n%s is absent: the peer's plume is skipped\n", peer.c_str());
    }
    return 0;
}
