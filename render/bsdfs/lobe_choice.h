// How a BSDF made of several parts picks the part to sample when a part carries a per-channel
// (coloured) share of the light.
#pragma once

#include "core/rgb.h"

namespace fluence::render {

// The probability of sampling a part that carries the share `share` (per channel, in [0, 1]) of
// the light: the average of the channels. A white (grey) share is then picked with exactly its
// share, so the sample weight carries no variance from the choice; a coloured one keeps every
// channel's weight within a factor 3 of its own share (share_c / average <= 3), where the largest
// channel would let the others' weights grow without bound as the share approaches 1.
inline float lobeProbability(const RGB& share) { return (share.x + share.y + share.z) * (1.0f / 3.0f); }

}  // namespace fluence::render
