#include "media/forced_collisions.h"

#include <algorithm>
#include <cmath>

namespace fluence::media {
namespace {

// The stretch of segment s within [0, tMax), and its rate s(t) (see DENSITY).
struct Stretch {
    double from = 0.0, to = 0.0, rate = 0.0;
    double depth() const { return rate * (to - from); }
};

Stretch stretchOf(const MajorantSegment& s, float tMax) {
    Stretch stretch{std::max(s.tMin, 0.0f), std::min(s.tMax, tMax), maxComponent(s.sigmaMaj)};
    if (!(stretch.to > stretch.from) || !(stretch.rate > 0.0)) stretch.rate = 0.0;
    return stretch;
}

}  // namespace

int sampleForcedCollisions(const Medium& medium, const MediumRay& ray, std::span<const float> u,
                           std::span<ForcedCollision> points) {
    const int count = static_cast<int>(u.size());
    double total = 0.0;  // S(tMax)
    medium.majorants(ray.origin, ray.direction, 0.0f, ray.tMax, [&](const MajorantSegment& s) {
        const Stretch stretch = stretchOf(s, ray.tMax);
        if (stretch.rate > 0.0) total += stretch.depth();
        return std::isfinite(total);
    });
    if (!(total > 0.0) || count == 0) return 0;
    const double mass = -std::expm1(-total);  // 1 - exp(-S(tMax))

    int k = 0;
    double before = 0.0;  // S at the current stretch's start
    Stretch last;         // the last stretch with a positive rate
    // The k-th point at distance t in `stretch`, drawn at `quantile` of the distribution (times mass).
    auto place = [&](const Stretch& stretch, double t, double quantile) {
        const float below = std::nextafter(static_cast<float>(stretch.to), 0.0f);  // inside [from, to)
        const float tf = std::clamp(static_cast<float>(t), static_cast<float>(stretch.from), below);
        const double density = stretch.rate * (1.0 - quantile) / mass;  // p(t) = s exp(-S(t)) / mass
        points[static_cast<std::size_t>(k)] = {tf, static_cast<float>(1.0 / (count * density))};
        ++k;
    };
    auto quantileOf = [&](int i) { return (i + double(u[static_cast<std::size_t>(i)])) / count * mass; };
    medium.majorants(ray.origin, ray.direction, 0.0f, ray.tMax, [&](const MajorantSegment& s) {
        const Stretch stretch = stretchOf(s, ray.tMax);
        if (stretch.rate <= 0.0) return true;
        const double after = before + stretch.depth();
        while (k < count) {
            const double quantile = quantileOf(k);
            const double depth = -std::log1p(-quantile);  // S(t_k)
            if (!(depth < after)) break;
            place(stretch, stretch.from + (depth - before) / stretch.rate, quantile);
        }
        before = after;
        last = stretch;
        return k < count;
    });
    while (k < count && last.rate > 0.0) place(last, last.to, quantileOf(k));  // rounding: past the end
    return k;
}

}  // namespace fluence::media
