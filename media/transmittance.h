// The transmittance estimators of media/, chosen by name: every caller that needs a transmittance
// (not a distance) asks here, so that a method is one option wherever it applies.
//   RatioTracking (media/ratio_tracking.h): residual ratio tracking on media/tracking.h's
//     majorant walk. Its throughput doubles as delta tracking's density of the same null points,
//     which the null-scattering MIS of a light sample against phase or BSDF sampling needs.
//   RayMarching (media/ray_marching_transmittance.h): the unbiased ray-marching estimator of
//     Kettunen et al. 2021. Samples no channel and no null point (pdfRatio 1), so it serves where
//     no other strategy is weighted against the shadow ray: delta lights, light that passed
//     through surfaces; and wherever a transmittance is wanted alone.
#pragma once

#include "media/ratio_tracking.h"
#include "media/ray_marching_transmittance.h"

namespace fluence::media {

enum class TransmittanceMethod { RatioTracking, RayMarching };

inline TransmittanceEstimate estimateTransmittance(TransmittanceMethod method, const Medium& medium,
                                                   const MediumRay& ray, int hero, SampleStream& stream) {
    return method == TransmittanceMethod::RayMarching ? rayMarchingTransmittance(medium, ray, hero, stream)
                                                      : ratioTrackingTransmittance(medium, ray, hero, stream);
}

}  // namespace fluence::media
