// Shared by the BSDF tests: incident directions and the Monte Carlo albedo of a BSDF.
#pragma once

#include <cmath>
#include <cstdint>

#include "core/random.h"
#include "core/sampling.h"
#include "render/bsdf.h"
#include "tests/support/statistics.h"

namespace fluence::test {

// The unit direction at `thetaDegrees` from +z, in the azimuth (cosPhi, sinPhi).
inline Vec3f incidentDirection(float thetaDegrees, float cosPhi = 1.0f, float sinPhi = 0.0f) {
    float t = thetaDegrees * kPi / 180.0f;
    return {std::sin(t) * cosPhi, std::sin(t) * sinPhi, std::cos(t)};
}

// The albedo (first channel) at wo: the mean of f cos / pdf over `samples` samples, failures
// counting 0.
inline MeanEstimate albedoEstimate(const render::Bsdf& bsdf, const Vec3f& wo, int samples, std::uint64_t seed) {
    MeanEstimate e;
    for (int n = 0; n < samples; ++n) {
        SampleStream rng(seed, 0, static_cast<std::uint64_t>(n));
        float uLobe = rng.next();
        auto s = bsdf.sample(wo, uLobe, rng.next2D());
        e.add(s ? s->f.x * std::abs(s->wi.z) / s->pdf : 0.0);
    }
    return e;
}

// The flux albedo (first channel) at wo: the mean weight of the importance mode's samples
// (render/bsdf.h, TRANSPORT MODE: the adjoint carries flux, so a refracted sample's 1 / eta^2 is
// undone), failures counting 0.
inline MeanEstimate fluxAlbedoEstimate(const render::Bsdf& bsdf, const Vec3f& wo, int samples, std::uint64_t seed) {
    MeanEstimate e;
    for (int n = 0; n < samples; ++n) {
        SampleStream rng(seed, 0, static_cast<std::uint64_t>(n));
        const float uLobe = rng.next();
        const auto s = bsdf.sample(wo, uLobe, rng.next2D(), render::Transport::Importance);
        e.add(s ? s->f.x * std::abs(s->wi.z) / s->pdf : 0.0);
    }
    return e;
}

}  // namespace fluence::test
