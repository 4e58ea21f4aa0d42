// What every transmittance estimator returns (media/ratio_tracking.h,
// media/ray_marching_transmittance.h; media/transmittance.h chooses between them): a weight per
// channel in the spectral-MIS form of media/tracking.h, f/p_hero and p_c/p_hero.
#pragma once

#include "core/rgb.h"
#include "media/tracking.h"

namespace fluence::media {

struct TransmittanceEstimate {
    RGB throughput{1.0f};  // f_c / p_h. Ratio tracking: the null points' Tmaj sigmaN and the last
                           // stretch's Tmaj, over the hero's density; this is also delta tracking's
                           // density of the same null points over p_h (delta tracking's pdf of a null
                           // point equals its f). Ray marching: the unbiased estimate of T_c itself.
    RGB pdfRatio{1.0f};    // p_c / p_h: the estimator's density had channel c been the hero (1 in
                           // every channel for an estimator that does not sample by channel)
    int collisions = 0;    // medium lookups made (tentative collisions, or ray-marching points): the work

    // The transmittance in each channel, unbiased when the hero was drawn uniformly for this
    // estimate alone (within a path, combine throughput and pdfRatio as media/tracking.h says).
    RGB estimate() const { return throughput / channelAverage(pdfRatio); }
};

}  // namespace fluence::media
