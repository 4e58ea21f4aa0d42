// Time samples and the value they give at a time code (USD's "Value Resolution" of time samples):
// the sample at that time; between two samples, linear interpolation when both are numeric
// values of one size and of a type that interpolates (not integers or bools), else the earlier
// sample, held; before the first and after the last sample, that sample. Next to a sample at an
// infinite time (-inf, inf), the finite neighbour's value (the limit of the interpolation).
#pragma once

#include <utility>
#include <vector>

#include "scene/value.h"

namespace fluence::usd {

using TimeSamples = std::vector<std::pair<double, Value>>;  // sorted by time

// The value `samples` (not empty) give at `time`; a value block (`None`) is returned as such.
Value valueAtTime(const TimeSamples& samples, double time);

}  // namespace fluence::usd
