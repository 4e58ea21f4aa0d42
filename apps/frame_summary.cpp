#include "apps/frame_summary.h"

#include <algorithm>
#include <cstdio>
#include <thread>

#include "integrators/adaptive_sampling.h"

namespace fluence::app {

namespace {

// The render's rays and samples, per second.
void printThroughput(const integrators::RenderStats& stats) {
    const integrators::RenderCounters& c = stats.counters;
    std::printf("  throughput   %.3f Msamples/s, %.3f Mrays/s (%llu rays: %llu camera, %llu bounce, %llu shadow)\n",
                double(stats.samples) / stats.seconds * 1e-6, double(c.rays()) / stats.seconds * 1e-6,
                static_cast<unsigned long long>(c.rays()), static_cast<unsigned long long>(c.camera),
                static_cast<unsigned long long>(c.bounce), static_cast<unsigned long long>(c.shadow));
    if (c.mediumCollisions > 0)
        std::printf("  media        %llu tentative collisions (medium lookups)\n",
                    static_cast<unsigned long long>(c.mediumCollisions));
    if (c.exactFlights > 0)
        std::printf("  exact        %llu grid cells walked by %llu exact flights\n",
                    static_cast<unsigned long long>(c.exactCells), static_cast<unsigned long long>(c.exactFlights));
    if (c.walkSteps > 0)
        std::printf("  interiors    %llu guided random-walk steps\n", static_cast<unsigned long long>(c.walkSteps));
    if (c.nonFiniteSamples > 0)
        std::fprintf(stderr, "fluence: warning: %llu samples were NaN or infinite and were discarded (please report)\n",
                     static_cast<unsigned long long>(c.nonFiniteSamples));
}

}  // namespace

std::string counted(std::size_t n, const std::string& singular, const std::string& plural) {
    return std::to_string(n) + " " + (n == 1 ? singular : (plural.empty() ? singular + "s" : plural));
}

void printFrameSummary(const RenderOptions& opt, const std::pair<int, int>& res, const BuiltFrame& built,
                       const RenderedFrame& frame, const FrameOutputs& outputs, const FrameTimes& times,
                       const WarningLog& warnings) {
    const integrators::RenderStats& stats = frame.stats;
    const integrators::RenderSettings& rs = frame.settings;
    const auto& st = built.scene->stats();
    const std::string& cameraPath = built.populated->cameraPath;
    std::printf("fluence: rendered %s\n", opt.scene.c_str());
    std::printf("  camera       %s\n", cameraPath.empty() ? "(default: framing the scene)" : cameraPath.c_str());
    std::printf("  image        %d x %d, %d spp, integrator %s, seed %llu, %d threads\n", res.first, res.second,
                stats.samplesPerPixel, built.integrator->name.c_str(), static_cast<unsigned long long>(opt.seed),
                opt.threads > 0 ? opt.threads : int(std::thread::hardware_concurrency()));
    std::printf("  scene        %s, %s, %s (%s), %s\n", counted(st.meshes, "mesh", "meshes").c_str(),
                counted(st.triangles, "triangle").c_str(), counted(st.lights, "light").c_str(),
                counted(st.emissiveTriangles, "emissive triangle").c_str(),
                counted(warnings.count(), "warning").c_str());
    if (integrators::AdaptiveSampling::enabled(rs))
        std::printf("  adaptive     %s %g: %.1f spp on average (%d to %d per pixel), the cost of %.1f uniform spp\n",
                    rs.targetError > 0.0 ? "target error" : "mean spp",
                    rs.targetError > 0.0 ? rs.targetError : rs.meanSamplesPerPixel,
                    double(stats.samples) / (double(res.first) * res.second),
                    std::min(rs.minSamples, stats.samplesPerPixel), stats.samplesPerPixel,
                    integrators::AdaptiveSampling::uniformSamplesOfTheSameCost(*frame.film));
    if (st.curves > 0)
        std::printf("  curves       %s, %s (Embree native curves)\n", counted(st.curves, "curve set").c_str(),
                    counted(st.curveSegments, "segment").c_str());
    if (st.pointSets > 0)
        std::printf("  points       %s, %s (Embree points)\n", counted(st.pointSets, "point set").c_str(),
                    counted(st.points, "point").c_str());
    if (st.instances > 0)
        std::printf("  instancing   %s placing %s (stored once)\n", counted(st.instances, "instance").c_str(),
                    counted(st.instancedTriangles, "triangle").c_str());
    std::printf("  time         parse %.3f s, build %.3f s, render %.3f s (%.3f s CPU), write %.3f s, total %.3f s\n",
                times.parse, times.build, stats.seconds, stats.cpuSeconds, times.write, times.total);
    printThroughput(stats);
    if (const std::string& note = stats.methodSummary; !note.empty()) std::printf("  method       %s\n", note.c_str());
    for (const std::string& path : outputs.files) std::printf("  output       %s\n", path.c_str());
    if (!outputs.preview.empty()) std::printf("  preview      %s\n", outputs.preview.c_str());
}

FrameSummary frameSummary(double time, const std::pair<int, int>& res, const BuiltFrame& built,
                          const RenderedFrame& frame, const FrameOutputs& outputs, const FrameTimes& times) {
    const integrators::RenderStats& stats = frame.stats;
    FrameSummary summary;
    summary.time = time;
    summary.output = outputs.files.front();
    summary.integrator = built.integrator->name;
    summary.camera = built.populated->cameraPath;
    summary.width = res.first;
    summary.height = res.second;
    summary.samplesPerPixel = stats.samplesPerPixel;
    summary.samples = stats.samples;
    summary.cameraRays = stats.counters.camera;
    summary.bounceRays = stats.counters.bounce;
    summary.shadowRays = stats.counters.shadow;
    summary.nonFiniteSamples = stats.counters.nonFiniteSamples;
    summary.buildSeconds = times.build;
    summary.renderSeconds = stats.seconds;
    summary.renderCpuSeconds = stats.cpuSeconds;
    summary.writeSeconds = times.write;
    summary.totalSeconds = times.total;
    return summary;
}

}  // namespace fluence::app
