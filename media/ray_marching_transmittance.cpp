#include "media/ray_marching_transmittance.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "media/ratio_tracking.h"

namespace fluence::media {
namespace {

// A segment of the ray clipped to [0, tMax), with its residual majorant w (one for all channels).
struct MarchSegment {
    float tMin, tMax;
    RGB sigmaMin;
    float w;
};

// The ray's segments, their minorants' optical depth, and the residual majorant's (tauR).
struct RayProfile {
    std::vector<MarchSegment> segments;  // only those with w > 0
    RGB tauMin{0.0f};
    float tauR = 0.0f;
    bool marchable = true;  // false: residual majorant over an infinite stretch
};

void profile(const Medium& medium, const MediumRay& ray, RayProfile& out) {
    medium.majorants(ray.origin, ray.direction, 0.0f, ray.tMax, [&](const MajorantSegment& s) {
        const float a = std::max(s.tMin, 0.0f), b = std::min(s.tMax, ray.tMax);
        if (!(a < b)) return true;
        const float length = b - a;
        for (int c = 0; c < 3; ++c)
            if (s.sigmaMin[c] > 0.0f) out.tauMin[c] += s.sigmaMin[c] * length;  // +inf over an infinite stretch
        const float w = maxComponent(vmax(s.sigmaMaj - s.sigmaMin, RGB(0.0f)));
        if (w <= 0.0f) return true;
        if (!std::isfinite(length)) {
            out.marchable = false;
            return false;
        }
        out.segments.push_back({a, b, s.sigmaMin, w});
        out.tauR += w * length;
        return true;
    });
}

// R(xi): the comb of `points` points at offset xi (see the header), per channel; counts its lookups.
RGB comb(const Medium& medium, const MediumRay& ray, const RayProfile& profile, int points, float xi, int& lookups) {
    const float du = profile.tauR / static_cast<float>(points);
    RGB sum(0.0f);
    float uStart = 0.0f;  // U at the current segment's start
    int j = 0;
    for (const MarchSegment& s : profile.segments) {
        const float uEnd = uStart + s.w * (s.tMax - s.tMin);
        const bool last = &s == &profile.segments.back();  // rounding: the last segment takes the rest
        for (; j < points; ++j) {
            const float u = (static_cast<float>(j) + xi) * du;
            if (u >= uEnd && !last) break;
            const float t = std::min(s.tMin + (u - uStart) / s.w, s.tMax);
            const MediumProperties m = medium.at(ray.at(t));
            sum += (m.sigmaA + m.sigmaS - s.sigmaMin) / s.w;
            ++lookups;
        }
        uStart = uEnd;
    }
    return sum * du;
}

}  // namespace

TransmittanceEstimate rayMarchingTransmittance(const Medium& medium, const MediumRay& ray, int hero,
                                               SampleStream& stream, const RayMarchingSettings& settings) {
    thread_local RayProfile p;  // reused: a shadow ray's segments without an allocation each
    p.segments.clear();
    p.tauMin = RGB(0.0f);
    p.tauR = 0.0f;
    p.marchable = true;
    profile(medium, ray, p);
    if (!p.marchable) return ratioTrackingTransmittance(medium, ray, hero, stream);

    TransmittanceEstimate e;
    RGB tau = p.tauMin;
    if (p.tauR > 0.0f) {
        const int points = std::max(1, static_cast<int>(std::ceil(p.tauR / settings.stepDepth)));
        const RGB control = comb(medium, ray, p, points, stream.next(), e.collisions);
        tau += control;
        // The order K >= 1, then e_k(X_1..X_K) built up one sample at a time (e[k] += e[k-1] X, k descending).
        int order = 1;
        while (stream.next() < settings.continuation) ++order;
        thread_local std::vector<RGB> elementary;
        elementary.assign(static_cast<std::size_t>(order) + 1, RGB(0.0f));
        elementary[0] = RGB(1.0f);
        for (int i = 1; i <= order; ++i) {
            const RGB x = control - comb(medium, ray, p, points, stream.next(), e.collisions);
            for (int k = i; k >= 1; --k) elementary[k] += elementary[k - 1] * x;
        }
        // sum_k e_k / (binomial(K, k) k! P(K >= k)), with binomial(K, k) k! = K! / (K - k)!.
        RGB series(0.0f);
        double fallingFactorial = 1.0, survival = 1.0;  // K! / (K - k)!, P(K >= k)
        for (int k = 0; k <= order; ++k) {
            if (k >= 1) fallingFactorial *= order - k + 1;
            if (k >= 2) survival *= settings.continuation;
            series += elementary[k] * static_cast<float>(1.0 / (fallingFactorial * survival));
        }
        e.throughput = series;
    }
    for (int c = 0; c < 3; ++c) e.throughput[c] *= std::exp(-tau[c]);
    return e;
}

}  // namespace fluence::media
