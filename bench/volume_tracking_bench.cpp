// Volume tracking benchmark: what the majorant grid saves when the media/ estimators actually run.
//
//   volume_tracking_bench [--stride N]      (every N-th pixel in x and y; default 4)
//
// The tools/make_smoke plume (usd_samples/smoke/smoke.vdb, densityScale 6, albedo 0.9 as in
// smoke.usda) seen by smoke.usda's camera (320 x 400), one ray per N-th pixel, each traced to
// infinity (the ground is ignored). For the default majorant grid (8 voxels per cell) and for one
// global majorant (a single cell), over the same rays (those that miss the volume included):
//   - free flights (media::sampleFreeFlight, delta tracking, 16 per ray): density lookups per flight,
//     and null collisions per real (scattering or absorbing) one;
//   - transmittance (media::ratioTrackingTransmittance, 16 per ray): density lookups per estimate;
//   - ns per flight and per estimate, one thread; both estimates are checked to agree between the
//     two grids (they must: the majorant only changes the cost).
// A density lookup is one GridMedium::at() call, counted by a wrapping medium.
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "bench/camera_rays.h"
#include "media/free_flight.h"
#include "media/ratio_tracking.h"
#include "volumes/grid_medium.h"

namespace {

using namespace fluence;
using Clock = std::chrono::steady_clock;

// A medium that counts its lookups.
class CountingMedium final : public media::Medium {
public:
    explicit CountingMedium(const media::Medium& inner) : inner_(inner) {}
    media::MediumProperties at(const Vec3f& p) const override {
        ++lookups;
        return inner_.at(p);
    }
    void majorants(const Vec3f& o, const Vec3f& d, float tMin, float tMax,
                   FunctionRef<bool(const media::MajorantSegment&)> visit) const override {
        inner_.majorants(o, d, tMin, tMax, visit);
    }
    mutable long long lookups = 0;

private:
    const media::Medium& inner_;
};

using Ray = bench::CameraRay;

// usd_samples/smoke/smoke.usda's camera: at (0.3, 1.6, 7.5) tilted 2 degrees down, apertures
// 19.2 x 24 at focal length 30, 320 x 400 pixels; Y up.
std::vector<Ray> smokeCameraRays(int stride) {
    const float tilt = 2.0f * 3.14159265f / 180.0f;
    return bench::cameraRays({0.3f, 1.6f, 7.5f}, Vec3f(0.3f, 1.6f - std::sin(tilt), 7.5f - std::cos(tilt)),
                             {0.0f, 1.0f, 0.0f}, 9.6f / 30.0f, 12.0f / 30.0f, 320, 400, stride);
}

struct Figures {
    double lookupsPerFlight = 0, nullPerReal = 0, nsPerFlight = 0, lookupsPerTransmittance = 0, nsPerTransmittance = 0;
    double meanTransmittance = 0, scatteredFraction = 0;
    int rays = 0;
};

Figures measure(const media::Medium& medium, const std::vector<Ray>& rays) {
    constexpr int kPerRay = 16;
    CountingMedium counting(medium);
    Figures f;
    long long flights = 0, real = 0, lookupsBefore = 0;
    double flightSeconds = 0, trSeconds = 0, trSum = 0;
    long long flightLookups = 0, trLookups = 0, estimates = 0;
    for (std::size_t r = 0; r < rays.size(); ++r) {
        const Ray& ray = rays[r];
        ++f.rays;
        auto t0 = Clock::now();
        lookupsBefore = counting.lookups;
        for (int i = 0; i < kPerRay; ++i) {
            SampleStream rng(3, r, std::uint64_t(i));
            media::FreeFlight flight = media::sampleFreeFlight(counting, {ray.origin, ray.direction},
                                                               media::sampleHeroChannel(rng.next()), rng);
            ++flights;
            real += flight.event != media::FlightEvent::Escaped;
        }
        flightSeconds += std::chrono::duration<double>(Clock::now() - t0).count();
        flightLookups += counting.lookups - lookupsBefore;
        t0 = Clock::now();
        lookupsBefore = counting.lookups;
        for (int i = 0; i < kPerRay; ++i) {
            SampleStream rng(5, r, std::uint64_t(i));
            media::TransmittanceEstimate tr = media::ratioTrackingTransmittance(
                counting, {ray.origin, ray.direction, 1e4f}, media::sampleHeroChannel(rng.next()), rng);
            trSum += tr.estimate().y;
            ++estimates;
        }
        trSeconds += std::chrono::duration<double>(Clock::now() - t0).count();
        trLookups += counting.lookups - lookupsBefore;
    }
    f.lookupsPerFlight = double(flightLookups) / double(flights);
    f.nullPerReal = real > 0 ? double(flightLookups - real) / double(real) : 0.0;
    f.nsPerFlight = 1e9 * flightSeconds / double(flights);
    f.lookupsPerTransmittance = double(trLookups) / double(estimates);
    f.nsPerTransmittance = 1e9 * trSeconds / double(estimates);
    f.meanTransmittance = trSum / double(estimates);
    f.scatteredFraction = double(real) / double(flights);
    return f;
}

}  // namespace

int main(int argc, char** argv) {
    int stride = 4;
    for (int i = 1; i + 1 < argc; ++i)
        if (std::strcmp(argv[i], "--stride") == 0) stride = std::max(1, std::atoi(argv[i + 1]));
    const std::string file = std::string(FLUENCE_SOURCE_DIR) + "/usd_samples/smoke/smoke.vdb";
    volumes::GridMediumParams params;
    params.densityScale = 6.0f;
    params.albedo = RGB(0.9f);
    std::vector<Ray> rays = smokeCameraRays(stride);
    std::printf(
        "volume tracking through %s, %zu camera rays (stride %d), 16 flights and 16 transmittance estimates per ray\n",
        file.c_str(), rays.size(), stride);
    std::printf("%-22s %6s %12s %12s %10s %14s %10s %8s %8s\n", "majorants", "rays", "lookups/flt", "null/real",
                "ns/flight", "lookups/trans", "ns/trans", "mean T", "real/flt");
    struct Variant {
        const char* name;
        volumes::MajorantGridOptions options;
    };
    for (const Variant& v : {Variant{"grid, 8 voxels/cell", {}}, Variant{"global (one cell)", {1e9, 1}}}) {
        volumes::GridMedium medium(volumes::FloatVdbGrid(file, "density"), params, {}, {}, v.options);
        Figures f = measure(medium, rays);
        std::printf("%-22s %6d %12.2f %12.2f %10.0f %14.2f %10.0f %8.4f %8.4f\n", v.name, f.rays, f.lookupsPerFlight,
                    f.nullPerReal, f.nsPerFlight, f.lookupsPerTransmittance, f.nsPerTransmittance, f.meanTransmittance,
                    f.scatteredFraction);
    }
    return 0;
}
