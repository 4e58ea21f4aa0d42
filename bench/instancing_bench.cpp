// Instancing benchmark: what sharing one prototype among N instances saves (build time, peak
// memory) and costs (ray-cast speed), against the same geometry copied into world space.
//
//   instancing_bench [--instances N[,N...]] [--subdivisions S] [--rays R]
//
// The prototype is an icosphere (20 * 4^S triangles; S = 4 by default: 5,120 triangles). The
// instances sit on a square grid with a per-instance rotation and scale. For each N, two fresh
// child processes (this executable again, so that each measures its own peak) build a
// render::RenderScene from a SceneDescription holding either one prototype and N instances, or N
// world-space copies, and then cast R rays (default 1,000,000) from above the grid, one thread.
// Figures: build seconds, peak memory growth (VmHWM after minus VmRSS before, in MiB, including
// the SceneDescription itself), triangles placed, Mrays/s, and the fraction of rays that hit
// (equal in both modes: the same surfaces). Copies are skipped above 12 M triangles.
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "bench/process_status.h"
#include "core/random.h"
#include "render/mesh_transform.h"
#include "render/render_scene.h"

namespace {

using namespace fluence;

// An icosphere of unit radius: an icosahedron whose triangles are split in four `subdivisions`
// times, new vertices pushed onto the sphere.
render::MeshDesc icosphere(int subdivisions) {
    render::MeshDesc mesh;
    mesh.name = "/rock";
    const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
    for (Vec3f p :
         {Vec3f(-1, t, 0), Vec3f(1, t, 0), Vec3f(-1, -t, 0), Vec3f(1, -t, 0), Vec3f(0, -1, t), Vec3f(0, 1, t),
          Vec3f(0, -1, -t), Vec3f(0, 1, -t), Vec3f(t, 0, -1), Vec3f(t, 0, 1), Vec3f(-t, 0, -1), Vec3f(-t, 0, 1)})
        mesh.positions.push_back(normalize(p));
    mesh.indices = {0, 11, 5, 0, 5, 1, 0, 1, 7, 0, 7, 10, 0, 10, 11, 1, 5, 9, 5, 11, 4,  11, 10, 2,  10, 7, 6, 7, 1, 8,
                    3, 9,  4, 3, 4, 2, 3, 2, 6, 3, 6, 8,  3, 8,  9,  4, 9, 5, 2, 4,  11, 6,  2,  10, 8,  6, 7, 9, 8, 1};
    for (int s = 0; s < subdivisions; ++s) {
        std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoints;
        auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
            auto [it, inserted] = midpoints.try_emplace({std::min(a, b), std::max(a, b)}, 0);
            if (inserted) {
                it->second = static_cast<std::uint32_t>(mesh.positions.size());
                mesh.positions.push_back(normalize(mesh.positions[a] + mesh.positions[b]));
            }
            return it->second;
        };
        std::vector<std::uint32_t> next;
        for (std::size_t i = 0; i < mesh.indices.size(); i += 3) {
            std::uint32_t a = mesh.indices[i], b = mesh.indices[i + 1], c = mesh.indices[i + 2];
            std::uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
            next.insert(next.end(), {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca});
        }
        mesh.indices = std::move(next);
    }
    return mesh;
}

std::vector<Matrix4> placements(int count) {
    int side = static_cast<int>(std::ceil(std::sqrt(double(count))));
    std::vector<Matrix4> out;
    for (int i = 0; i < count; ++i) {
        double x = (i % side - side / 2.0) * 3.0, z = (i / side - side / 2.0) * 3.0;
        out.push_back(Matrix4::translate({x, 0, z}) * Matrix4::rotateY(37.0 * i) *
                      Matrix4::scale(Vec3d(0.6 + 0.4 * ((i * 7) % 10) / 10.0)));
    }
    return out;
}

// The measured child: prints "key value" lines.
int child(bool instanced, int count, int subdivisions, long rays) {
    long rss0 = bench::statusKiB("VmRSS");
    auto start = std::chrono::steady_clock::now();
    render::SceneDescription scene;
    render::MeshDesc rock = icosphere(subdivisions);
    std::vector<Matrix4> where = placements(count);
    if (instanced) {
        scene.prototypes.push_back({"/rock", {rock}});
        for (const Matrix4& m : where) scene.instances.push_back({0, m, ""});
    } else {
        for (const Matrix4& m : where) scene.meshes.push_back(render::transformMesh(rock, m));
    }
    render::RenderScene built(scene);
    double buildSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    long hwm = bench::statusKiB("VmHWM");

    int side = static_cast<int>(std::ceil(std::sqrt(double(count))));
    float extent = side * 1.5f;
    SampleStream random(1, 0, 0);
    long hits = 0;
    start = std::chrono::steady_clock::now();
    for (long i = 0; i < rays; ++i) {
        Vec3f origin((random.next() * 2 - 1) * extent, 20.0f, (random.next() * 2 - 1) * extent);
        Vec3f target((random.next() * 2 - 1) * extent, 0.0f, (random.next() * 2 - 1) * extent);
        if (built.intersect({origin, normalize(target - origin)})) ++hits;
    }
    double raySeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("build %.4f\nmemory %.1f\ntriangles %zu\nmrays %.3f\nhits %.4f\n", buildSeconds, (hwm - rss0) / 1024.0,
                instanced ? built.stats().instancedTriangles : built.stats().triangles, rays / raySeconds * 1e-6,
                double(hits) / rays);
    return 0;
}

std::map<std::string, double> runChild(bool instanced, int count, int subdivisions, long rays) {
    int pipeFds[2];
    if (pipe(pipeFds) != 0) std::exit(1);
    pid_t pid = fork();
    if (pid == 0) {
        dup2(pipeFds[1], STDOUT_FILENO);
        close(pipeFds[0]);
        std::string n = std::to_string(count), s = std::to_string(subdivisions), r = std::to_string(rays);
        execl("/proc/self/exe", "instancing_bench", "--child", instanced ? "instanced" : "copied", n.c_str(), s.c_str(),
              r.c_str(), static_cast<char*>(nullptr));
        _exit(127);
    }
    close(pipeFds[1]);
    std::string text;
    char buffer[4096];
    for (ssize_t got; (got = read(pipeFds[0], buffer, sizeof buffer)) > 0;)
        text.append(buffer, static_cast<std::size_t>(got));
    close(pipeFds[0]);
    int status = 0;
    waitpid(pid, &status, 0);
    std::map<std::string, double> figures;
    std::istringstream in(text);
    for (std::string key; in >> key;) in >> figures[key];
    return figures;
}

// Copies beyond this many triangles would take several GiB: not run.
constexpr double kMaxCopiedTriangles = 12e6;

}  // namespace

int main(int argc, char** argv) {
    std::vector<int> counts = {100, 1000, 10000, 100000};
    int subdivisions = 4;
    long rays = 1000000;
    for (int i = 1; i < argc; ++i) {
        std::string arg = argv[i];
        if (arg == "--child" && i + 4 < argc)
            return child(std::string(argv[i + 1]) == "instanced", std::atoi(argv[i + 2]), std::atoi(argv[i + 3]),
                         std::atol(argv[i + 4]));
        if (arg == "--instances" && i + 1 < argc) {
            counts.clear();
            std::stringstream list(argv[++i]);
            for (std::string n; std::getline(list, n, ',');) counts.push_back(std::stoi(n));
        } else if (arg == "--subdivisions" && i + 1 < argc) {
            subdivisions = std::atoi(argv[++i]);
        } else if (arg == "--rays" && i + 1 < argc) {
            rays = std::atol(argv[++i]);
        } else {
            std::fprintf(stderr, "usage: instancing_bench [--instances N[,N...]] [--subdivisions S] [--rays R]\n");
            return 2;
        }
    }
    std::printf("prototype: icosphere, %d triangles; %ld rays per run, one thread\n\n", 20 << (2 * subdivisions), rays);
    std::printf("%10s  %-9s  %12s  %9s  %11s  %8s  %6s\n", "instances", "mode", "triangles", "build s", "memory MiB",
                "Mrays/s", "hits");
    for (int count : counts)
        for (bool instanced : {true, false}) {
            if (!instanced && double(count) * (20 << (2 * subdivisions)) > kMaxCopiedTriangles) {
                std::printf("%10d  %-9s  (skipped: more than %.0f M triangles)\n", count, "copied",
                            kMaxCopiedTriangles * 1e-6);
                continue;
            }
            auto f = runChild(instanced, count, subdivisions, rays);
            if (f.empty()) {
                std::printf("%10d  %-9s  (failed)\n", count, instanced ? "instanced" : "copied");
                continue;
            }
            std::printf("%10d  %-9s  %12.0f  %9.3f  %11.1f  %8.3f  %6.3f\n", count, instanced ? "instanced" : "copied",
                        f["triangles"], f["build"], f["memory"], f["mrays"], f["hits"]);
        }
    return 0;
}
