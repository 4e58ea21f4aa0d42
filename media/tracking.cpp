#include "media/tracking.h"

#include <cmath>

namespace fluence::media {
namespace {

// exp(-sigma * length) per channel, and exactly 1 where sigma is 0, so that an unbounded stretch
// of empty space is transparent (not exp(-0 * inf) = NaN). A channel whose sigma equals the one
// before's takes its value instead of computing it again (a grey medium: one exp, not three).
RGB transmittance(const RGB& sigma, float length) {
    RGB t(1.0f);
    for (int c = 0; c < 3; ++c)
        if (sigma[c] > 0.0f) t[c] = c > 0 && sigma[c] == sigma[c - 1] ? t[c - 1] : std::exp(-sigma[c] * length);
    return t;
}

}  // namespace

MajorantTransmittance trackMajorants(const Medium& medium, const MediumRay& ray, TrackingRate rate, int hero,
                                     SampleStream& stream, FunctionRef<bool(const TentativeCollision&)> atCollision) {
    MajorantTransmittance sinceLast;
    bool stopped = false;
    medium.majorants(ray.origin, ray.direction, 0.0f, ray.tMax, [&](const MajorantSegment& segment) {
        if (stopped) return false;  // a medium that visits on after being told to stop
        const RGB residual = vmax(segment.sigmaMaj - segment.sigmaMin, RGB(0.0f));
        const float heroRate = (rate == TrackingRate::Majorant ? segment.sigmaMaj : residual)[hero];
        const float end = std::min(segment.tMax, ray.tMax);
        float t = std::max(segment.tMin, 0.0f);
        while (t < end) {
            // An exponential step at the hero's rate (1 - u is in (0, 1], so the log is finite).
            const float step =
                heroRate > 0.0f ? -std::log(1.0f - stream.next()) / heroRate : std::numeric_limits<float>::infinity();
            if (!(step < end - t)) {
                sinceLast.tMaj *= transmittance(segment.sigmaMaj, end - t);
                sinceLast.tResidual *= transmittance(residual, end - t);
                return true;
            }
            t += step;
            const Vec3f p = ray.at(t);
            const TentativeCollision collision{t,
                                               p,
                                               medium.at(p),
                                               segment.sigmaMaj,
                                               segment.sigmaMin,
                                               sinceLast.tMaj * transmittance(segment.sigmaMaj, step),
                                               sinceLast.tResidual * transmittance(residual, step)};
            sinceLast = {};
            if (!atCollision(collision)) {
                stopped = true;
                return false;
            }
        }
        return true;
    });
    return stopped ? MajorantTransmittance{} : sinceLast;
}

}  // namespace fluence::media
