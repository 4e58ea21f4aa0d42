// Test-only media with closed forms, shared by the media tests: a linear ramp of extinction along
// x, and a wrapper that loosens (or breaks) another medium's majorants and minorants; and the
// state of a random walk through a medium, as a volume path tracer takes it.
#pragma once

#include <algorithm>
#include <cmath>

#include "core/random.h"
#include "media/free_flight.h"
#include "media/medium.h"
#include "media/phase.h"
#include "media/tracking.h"

namespace fluence::test {

using media::MajorantSegment;
using media::Medium;
using media::MediumProperties;

// sigmaT(x) = a + b x for 0 <= x < length, vacuum elsewhere; sigmaS = albedo sigmaT, sigmaA the
// rest. Along a ray that starts at x = 0 and runs along +x, T(d) = exp(-(a d + b d^2 / 2)) for
// d <= length. Its majorants cut the slab's stretch of a ray into `segments` equal pieces, each
// bounded by sigmaT at its ends (a linear function's extremes), the minorant too if asked.
class RampMedium final : public Medium {
public:
    RampMedium(RGB a, RGB b, float length, int segments, bool minorants, RGB albedo = RGB(0.0f), float g = 0.0f)
        : a_(a), b_(b), length_(length), segments_(segments), minorants_(minorants), albedo_(albedo), g_(g) {}

    RGB sigmaT(float x) const { return x >= 0.0f && x < length_ ? a_ + b_ * x : RGB(0.0f); }

    MediumProperties at(const Vec3f& p) const override {
        const RGB s = sigmaT(p.x);
        return {s * (RGB(1.0f) - albedo_), s * albedo_, RGB(0.0f), g_};
    }

    void majorants(const Vec3f& origin, const Vec3f& direction, float tMin, float tMax,
                   FunctionRef<bool(const MajorantSegment&)> visit) const override {
        // The stretch of the ray inside 0 <= x < length.
        float t0 = tMin, t1 = tMax;
        if (direction.x != 0.0f) {
            float ta = (0.0f - origin.x) / direction.x, tb = (length_ - origin.x) / direction.x;
            t0 = std::max(t0, std::min(ta, tb));
            t1 = std::min(t1, std::max(ta, tb));
        } else if (!(origin.x >= 0.0f && origin.x < length_)) {
            return;
        }
        if (!(t0 < t1)) return;
        for (int i = 0; i < segments_; ++i) {
            float s0 = t0 + (t1 - t0) * i / segments_,
                  s1 = i + 1 == segments_ ? t1 : t0 + (t1 - t0) * (i + 1) / segments_;
            RGB e0 = a_ + b_ * (origin.x + s0 * direction.x), e1 = a_ + b_ * (origin.x + s1 * direction.x);
            if (!visit(MajorantSegment{s0, s1, vmax(e0, e1), minorants_ ? vmin(e0, e1) : RGB(0.0f)})) return;
        }
    }

private:
    RGB a_, b_;
    float length_;
    int segments_;
    bool minorants_;
    RGB albedo_;
    float g_;
};

// A configuration of RampMedium and a ray through it from x = 0 to x = 2, as the transmittance
// tests take them: gray and chromatic, one or several segments, with and without minorants, along
// the x axis or obliquely.
struct RampCase {
    const char* name;
    RGB a, b;
    int segments;
    bool minorants, oblique;

    RampMedium medium() const { return RampMedium(a, b, 3.0f, segments, minorants); }
    media::MediumRay ray() const {
        const Vec3f direction = oblique ? normalize(Vec3f(1.0f, 0.7f, -0.4f)) : Vec3f(1.0f, 0.0f, 0.0f);
        return {Vec3f(0.0f), direction, kLength / direction.x};
    }
    // T = exp(-(a d + b d^2 / 2) / cos), d = 2 and cos the direction's x component.
    RGB transmittance() const {
        const float cos = ray().direction.x;
        RGB t;
        for (int c = 0; c < 3; ++c) t[c] = std::exp(-(a[c] * kLength + b[c] * kLength * kLength / 2.0f) / cos);
        return t;
    }
    static constexpr float kLength = 2.0f;
};

inline const RampCase kRampCases[] = {
    {"gray ramp, 1 segment", RGB(0.2f), RGB(0.8f), 1, false, false},
    {"gray ramp, 6 segments", RGB(0.2f), RGB(0.8f), 6, false, false},
    {"gray ramp, 6 segments with minorants, oblique", RGB(0.2f), RGB(0.8f), 6, true, true},
    {"chromatic ramp, 4 segments with minorants", RGB(0.1f, 1.0f, 2.0f), RGB(1.5f, 0.0f, -0.6f), 4, true, false},
    {"chromatic ramp with an empty channel", RGB(0.0f, 0.5f, 3.0f), RGB(0.0f, 1.0f, 0.2f), 3, false, true},
};

// Another medium with its majorants scaled by `majorantScale` and its minorants by
// `minorantScale`: (2, 0) loosens the bounds (null collisions, plain ratio tracking), a
// majorant scale below 1 or a minorant scale above 1 breaks them.
class RescaledBoundsMedium final : public Medium {
public:
    RescaledBoundsMedium(const Medium& inner, float majorantScale, float minorantScale)
        : inner_(inner), majorantScale_(majorantScale), minorantScale_(minorantScale) {}

    MediumProperties at(const Vec3f& p) const override { return inner_.at(p); }

    void majorants(const Vec3f& origin, const Vec3f& direction, float tMin, float tMax,
                   FunctionRef<bool(const MajorantSegment&)> visit) const override {
        inner_.majorants(origin, direction, tMin, tMax, [&](const MajorantSegment& s) {
            return visit(MajorantSegment{s.tMin, s.tMax, s.sigmaMaj * majorantScale_, s.sigmaMin * minorantScale_});
        });
    }

private:
    const Medium& inner_;
    float majorantScale_, minorantScale_;
};

// A path's state: its hero, throughput beta = f / p_h and pdf ratios rU = p_c / p_h.
struct Walk {
    Vec3f p{0.0f}, w{0.0f, 0.0f, 1.0f};
    int hero = 0;
    RGB beta{1.0f}, rU{1.0f};
    int scatterings = 0;

    // One flight to distance tMax; at a scattering, the next direction from the phase function.
    media::FreeFlight step(const Medium& medium, float tMax, SampleStream& rng) {
        media::FreeFlight flight = media::sampleFreeFlight(medium, {p, w, tMax}, hero, rng);
        beta *= flight.throughput;
        rU *= flight.pdfRatio;
        if (flight.event == media::FlightEvent::Scattered) {
            media::PhaseSample s = media::HenyeyGreenstein(flight.properties.g).sample(-w, rng.next2D());
            beta *= s.p / s.pdf;
            p = flight.p;
            w = s.wi;
            ++scatterings;
        }
        return flight;
    }
};

}  // namespace fluence::test
