// A checker of a medium's majorant segments against its coefficients along a ray (the contract in
// media/medium.h, MAJORANTS and MINORANTS), for every medium's tests: a majorant below sigmaT, or
// a minorant above it, biases every tracking estimator silently, so each medium's tests call
//     MajorantCheck check = majorantsBound(medium, ray);
//     EXPECT_TRUE(check.bound) << check.report;
// on rays through its interesting parts (pbrt-v4 checks its grids' majorants the same way).
//
// It checks that the segments come in increasing t without overlapping and that
// 0 <= sigmaMin <= sigmaMaj (finite); that the medium stops visiting when told to; and, at
// `pointsPerStretch` evenly spaced points (and the start) of every segment and of every gap
// between them within [0, ray.tMax), that sigmaMin <= sigmaT <= sigmaMaj in every channel in a
// segment and sigmaT = 0 in a gap, all up to a relative tolerance of kMajorantTolerance (float
// rounding of an interpolated density). Points are deterministic; a sampled check can miss a
// violation narrower than their spacing, so rays should cross the medium's fine structure. An
// unbounded ray is checked up to the end of its last bounded segment.
#pragma once

#include <string>

#include "media/medium.h"
#include "media/tracking.h"

namespace fluence::media {

inline constexpr float kMajorantTolerance = 1e-5f;

struct MajorantCheck {
    bool bound = true;   // every check passed
    std::string report;  // the first violations found, one per line
};

MajorantCheck majorantsBound(const Medium& medium, const MediumRay& ray, int pointsPerStretch = 32);

}  // namespace fluence::media
