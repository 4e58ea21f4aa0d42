// The Beckmann microfacet distribution, the D of Cook & Torrance (1982).
//
//   D(h) = exp(-tan^2 theta_h / m^2) / (pi m^2 cos^4 theta_h)
//
// m is the RMS slope of the microfacets. This is Beckmann's distribution normalised as
// projected microfacet area (the integral of D(h) cos theta_h over the hemisphere is 1;
// tests/render/bsdf_microfacet_test.cpp checks it). Microfacet normals have h.z > 0.
#pragma once

#include "core/vec.h"

namespace fluence::render {

class BeckmannDistribution {
public:
    explicit BeckmannDistribution(float m) : m_(m) {}

    float D(const Vec3f& h) const;
    // A microfacet normal with density normalPdf(h) = D(h) cos theta_h (solid angle):
    // tan^2 theta_h = -m^2 ln(1 - u.x), phi = 2 pi u.y.
    Vec3f sampleNormal(Vec2f u) const;
    float normalPdf(const Vec3f& h) const { return D(h) * h.z; }

private:
    float m_;
};

}  // namespace fluence::render
