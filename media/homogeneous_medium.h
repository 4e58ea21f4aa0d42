// A homogeneous medium: constant sigmaA, sigmaS, emission and Henyey-Greenstein g everywhere
// (pbrt-v4's HomogeneousMedium, Pharr, Jakob & Humphreys, "Physically Based Rendering", 4th ed.,
// section 11.4.1). Conventions are those of media/medium.h.
//
// Its majorants are one segment over the whole requested range with sigmaMaj = sigmaMin = sigmaT:
// the bounds are exact, so delta tracking never meets a null collision and ratio tracking draws
// no tentative collision at all (its transmittance is exactly exp(-sigmaT t)). The range may be
// unbounded (tMax = infinity): an infinite medium. Its exact extinction (media/medium.h) is one
// constant piece over the range.
#pragma once

#include "media/medium.h"

namespace fluence::media {

class HomogeneousMedium final : public Medium {
public:
    explicit HomogeneousMedium(const MediumProperties& properties);

    MediumProperties at(const Vec3f&) const override { return properties_; }
    void majorants(const Vec3f& origin, const Vec3f& direction, float tMin, float tMax,
                   FunctionRef<bool(const MajorantSegment&)> visit) const override;
    bool hasExactExtinction() const override { return true; }
    void extinctionPieces(const Vec3f& origin, const Vec3f& direction, float tMin, float tMax,
                          FunctionRef<bool(const ExtinctionPiece&)> visit) const override;

private:
    MediumProperties properties_;
};

}  // namespace fluence::media
