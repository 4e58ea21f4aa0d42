// Frame tokens in output paths, as Houdini's husk and farm tools write them:
//   $F      the frame number (the time code rounded to an integer), unpadded: 7
//   $F4     the same padded with zeros to 4 digits (any digit 1-9): 0007
//   $FF     the time code itself, shortest form: 7.5
//   %04d    printf style, padded to the width given (%d unpadded)
// A negative frame keeps its sign before the padding (-007 for $F4 of -7).
#pragma once

#include <string>

namespace fluence::app {

// Whether `pattern` holds a frame token.
bool hasFrameToken(const std::string& pattern);

// `pattern` with every frame token replaced by the frame at time code `time`.
std::string expandFrameTokens(const std::string& pattern, double time);

}  // namespace fluence::app
