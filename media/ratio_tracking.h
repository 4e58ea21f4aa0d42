// Transmittance by (residual) ratio tracking (Novak, Selle & Jarosz 2014, "Residual ratio tracking
// for estimating attenuation in participating media", the minorant as the control extinction),
// with the spectral MIS of Miller et al. 2019: the derivation, and how an integrator combines the
// result with next-event estimation, are in media/tracking.h (THE ESTIMATORS, SPECTRAL MIS).
//
// Tentative collisions are drawn at the hero's residual rate sigmaMaj - sigmaMin; each multiplies
// channel c's weight by Tmaj_c sigmaN_c over the hero's density Tres_h (sigmaMaj_h - sigmaMin_h),
// and the last stretch by Tmaj_c / Tres_h. Through a homogeneous medium (sigmaMin = sigmaMaj =
// sigmaT) no collision is drawn and the estimate is exactly exp(-sigmaT t). The walk stops early
// once every channel's weight is 0. tMax must be finite unless the residual rate vanishes beyond
// some distance (otherwise the walk runs on until the weights underflow).
#pragma once

#include "core/random.h"
#include "core/rgb.h"
#include "media/medium.h"
#include "media/tracking.h"
#include "media/transmittance_estimate.h"

namespace fluence::media {

// The transmittance of ray.origin -> ray.at(ray.tMax) through `medium`, drawn with hero channel `hero`.
TransmittanceEstimate ratioTrackingTransmittance(const Medium& medium, const MediumRay& ray, int hero,
                                                 SampleStream& stream);

}  // namespace fluence::media
